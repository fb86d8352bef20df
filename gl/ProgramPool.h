// Linked programs outlive their owners. A driver pays for a fresh program object's first use (on
// the H200 ~2.3 ms of a 10k-element solve's first pass, docs/bench/h200-2026-12-05.md), so a
// process that builds solvers again and again (bench rows, adaptive rounds, sweeps, the direct
// split) would pay it every time. A Program destroyed goes back to this pool, keyed by its
// expanded sources, and the next request for the same sources takes it, its uniforms restored
// to their values after linking: as a fresh link would give it. One owner at a time, so no
// uniform one solver sets is seen by another. The pool lives with the backend's context.
#pragma once
#include <string>

#include "gl/GL.h"

namespace hemirad::gl {

GLuint takeProgram(const std::string& key);           // an idle program of these sources, or 0
void poolProgram(GLuint id, const std::string& key);  // a freshly linked one: its uniforms are noted
bool returnProgram(GLuint id);                        // back to the pool; false: not pooled, delete it
void openProgramPool();                               // a context is current (RenderBackend)
void closeProgramPool();                              // deletes the idle ones before the context goes
std::size_t idlePrograms();

}  // namespace hemirad::gl
