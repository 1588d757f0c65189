#version 460
// interpolate.glsl: the staged walk (GPUs, groomed strands), with its shared memory.
#define INTERPOLATE_STAGED
#include "interpolate.glsl"
