// The light at a shaded point, for the shading passes: sampleLight is shared with the host
// (shared/light.h); the shadow slot is the shaders' alone.
#ifndef HP_LIGHT_GLSL
#define HP_LIGHT_GLSL
#include "shared/light.h"

// The light's shadow slot (shared/opacity.h), or -1 when it casts no hair shadow.
int lightSlot(FrameLight light) { return int(light.direction.w); }
#endif
