#version 460
#include "shared/selftest.h"

layout(push_constant) uniform Push { FlatDrawPush push; };
layout(location = 0) out vec4 color;

void main() { color = push.color; }
