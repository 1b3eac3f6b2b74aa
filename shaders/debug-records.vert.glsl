#version 300 es
// Debug wireframe of the shadow records, vertex stage: every record's outline as lines, two
// vertices per side and RECORD_TEXELS * 2 sides per record (the padding repeats the last point, so
// its sides have no length). No attributes: vertex i belongs to record i / (RECORD_TEXELS * 4).
precision highp float;
precision highp sampler2D;

uniform sampler2D u_records;
uniform mat4 u_viewProjection;

vec2 pointOf(int record, int point) {
  int texel = record * RECORD_TEXELS + point / 2;
  vec4 two = texelFetch(u_records, ivec2(texel % TEXTURE_WIDTH, texel / TEXTURE_WIDTH), 0);
  return point % 2 == 0 ? two.xy : two.zw;
}

void main() {
  const int points = RECORD_TEXELS * 2;
  int record = gl_VertexID / (2 * points);
  int side = (gl_VertexID / 2) % points;
  int point = gl_VertexID % 2 == 0 ? side : (side + 1) % points;
  // The side from the last point back to the first closes the outline.
  gl_Position = u_viewProjection * vec4(pointOf(record, point), 0.0, 1.0);
}
