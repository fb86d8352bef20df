// The one way GL reaches hemirad: glad's GL 4.5 core function pointers, filled by the
// current backend. Never link libGL/libOpenGL (with glvnd's libGL first, direct gl* calls
// under an OSMesa context return NULL).
#pragma once
#include <glad/gl.h>
