// The viewer's worker thread: it owns the GL backend and everything on it (solver state,
// solver, renderer); every glad call of the viewer happens here.
#pragma once
#include "src/scene/Scene.h"
#include "src/viewer/Viewer.h"
#include "src/viewer/ViewerLink.h"

namespace hemirad {

// Solves and renders frames for `link` until link.stop; an error ends it and is left in
// link.error (the window thread rethrows it).
void runViewerWorker(const ViewerOptions& options, const Scene& scene, ViewerLink& link);

}  // namespace hemirad
