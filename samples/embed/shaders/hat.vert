#version 460
// The application's occluder: a flat cap, a disc over the head's crown in the head's axes, kSegments wedges
// of one triangle each from gl_VertexIndex. Drawn into each framed slot's layer of hairpipe's heads' depth
// shadow map (depth only, with the map's light transform) and into the application's view.
layout(push_constant) uniform Push {
  mat4 transform;  // the head's axes to clip space: viewProj x the head's placement
  vec4 disc;       // x: radius, y: height above the head's origin, z: segments
  vec4 color;      // the visible pass's
};

void main() {
  int segment = gl_VertexIndex / 3, corner = gl_VertexIndex % 3;  // corner 0: the centre; 1, 2: the rim
  int segments = int(disc.z);
  // The rim's points by index modulo the count, so the last wedge closes on the first one's point exactly.
  float angle = 6.2831853 * float((segment + corner - 1) % segments) / disc.z;
  float radius = corner == 0 ? 0.0 : disc.x;
  gl_Position = transform * vec4(radius * cos(angle), disc.y, -radius * sin(angle), 1.0);
}
