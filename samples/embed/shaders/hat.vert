#version 460
// The application's occluder: a hat's brim, a flat ring of kSegments quads around the head's crown in the
// head's axes; 6 vertices a segment (two triangles) from gl_VertexIndex. Drawn twice: into
// hairpipe's heads' depth shadow map (depth only, with the map's light transform) and into the application's view.
layout(push_constant) uniform Push {
  mat4 transform;  // the head's axes to clip space: viewProj x the head's placement
  vec4 ring;   // x: inner radius, y: outer radius, z: height above the head's origin, w: segments
  vec4 color;  // the visible pass's
};

void main() {
  const int corners[6] = int[6](0, 1, 2, 2, 1, 3);  // two triangles per segment: (inner, outer) x (a, a + 1)
  int segment = gl_VertexIndex / 6, corner = corners[gl_VertexIndex % 6];
  float angle = 6.2831853 * float(segment + (corner >> 1)) / ring.w;
  float radius = (corner & 1) == 0 ? ring.x : ring.y;
  vec3 local = vec3(radius * cos(angle), ring.z, -radius * sin(angle));
  gl_Position = transform * vec4(local, 1.0);
}
