#version 300 es
// The shadow records (src/shadow/shadowLayout.ts), vertex stage, no attributes. As outlines
// (the debug wireframe, drawn as LINES): two vertices per side and RECORD_TEXELS * 2 sides per
// record, vertex i of record i / (RECORD_TEXELS * 4); the padding repeats the last point, so its
// sides have no length. With FILLED (the hull mask, drawn as TRIANGLES): each record's convex quad as
// the triangles (0, 1, 2) and (0, 2, 3), vertex i of record i / 6; a triangle record repeats its
// last point, so its second triangle has no area.
precision highp float;
precision highp sampler2D;

uniform sampler2D u_records;
uniform mat4 u_viewProjection;

vec2 pointOf(int record, int point) {
  int texel = record * RECORD_TEXELS + point / 2;
  vec4 two = texelFetch(u_records, ivec2(texel & (TEXTURE_WIDTH - 1), texel >> TEXTURE_WIDTH_BITS), 0);
  return point % 2 == 0 ? two.xy : two.zw;
}

#ifdef FILLED
const int CORNERS[6] = int[6](0, 1, 2, 0, 2, 3);

void main() {
  gl_Position = u_viewProjection * vec4(pointOf(gl_VertexID / 6, CORNERS[gl_VertexID % 6]), 0.0, 1.0);
}
#else
void main() {
  const int points = RECORD_TEXELS * 2;
  int record = gl_VertexID / (2 * points);
  int side = (gl_VertexID / 2) % points;
  int point = gl_VertexID % 2 == 0 ? side : (side + 1) % points;
  // The side from the last point back to the first closes the outline.
  gl_Position = u_viewProjection * vec4(pointOf(record, point), 0.0, 1.0);
}
#endif
