// The viewer's worker thread: it owns the GL backend and everything on it (solver state,
// solver, renderer); every glad call of the viewer happens here.
#pragma once
#include <string>
#include <vector>

#include "src/scene/Scene.h"
#include "src/viewer/Viewer.h"
#include "src/viewer/ViewerLink.h"

namespace hemirad {

// Solves and renders frames for `link` until link.stop; an error ends it and is left in
// link.error (the window thread rethrows it).
void runViewerWorker(const ViewerOptions& options, const Scene& scene, ViewerLink& link);
// The --method names the viewer runs, each with a worker of its own.
std::vector<std::string> viewerMethods();

}  // namespace hemirad
