#version 300 es
// Shadow mask, vertex stage: turns each hull edge into a quad that covers every point the edge can
// hide any part of the light disk from. The two far corners are pushed along the outer tangents of
// the disk through the edge's end points, far beyond the light's bounds (the scissor cuts them).
// They stay finite rather than at w = 0: SwiftShader culls every triangle with a w = 0 vertex.
precision highp float;
#include "shadow-edge"

flat out ivec2 v_hull;

void main() {
  vec2 start, end;
  ivec2 hull;
  edgeOf(start, end, hull);
  // Corners in fan order: start, end, end projected, start projected.
  vec2 corner = vec2(gl_VertexID == 1 || gl_VertexID == 2 ? 1.0 : 0.0, gl_VertexID >= 2 ? 1.0 : 0.0);
  vec2 point = mix(start, end, corner.x);
  vec2 other = mix(end, start, corner.x);
  // The outer tangent from the disk through the point leans away from the edge's other end.
  vec2 tangent = diskTangent(point, other, -1.0);
  gl_Position = u_viewProjection * vec4(point + tangent * (corner.y * u_projectionLength), 0.0, 1.0);
  // Behind the umbra prepass's depth (see shadow-mask.umbra.vert.glsl).
  gl_Position.z = 0.0;
  v_hull = hull;
}
