#version 300 es
// Shadow mask, umbra prepass, vertex stage: per edge, the region where that edge alone hides the
// whole light disk: behind the edge, between the disk's tangents through its ends that lean towards
// each other. Drawn first, at the front depth and as fully hidden, so that the full shadow pass's
// fragments there fail the depth test early and do not run. The region is convex: a triangle when
// the two tangents meet behind the edge, else a quad pushed far beyond the light's bounds. When the
// disk reaches the edge's line no point is hidden by that edge alone: the quad collapses.
precision highp float;
#include "shadow-edge"

void main() {
  vec2 start, end;
  ivec2 hull;
  edgeOf(start, end, hull);
  vec2 startTangent = diskTangent(start, end, 1.0);
  vec2 endTangent = diskTangent(end, start, 1.0);
  vec2 edge = end - start;
  vec2 normal = normalize(vec2(-edge.y, edge.x));
  bool diskCrossesLine = abs(dot(u_lightPosition - start, normal)) <= u_lightRadius;
  // Where start + s * startTangent meets end + t * endTangent.
  float denominator = startTangent.x * endTangent.y - startTangent.y * endTangent.x;
  float s = (edge.x * endTangent.y - edge.y * endTangent.x) / denominator;
  float t = (edge.x * startTangent.y - edge.y * startTangent.x) / denominator;
  bool meet = abs(denominator) > 1e-9 && s > 0.0 && t > 0.0 && s < u_projectionLength;
  vec2 startFar = meet ? start + startTangent * s : start + startTangent * u_projectionLength;
  vec2 endFar = meet ? startFar : end + endTangent * u_projectionLength;
  // Corners in fan order, as the shadow quads (same winding, so the same faces are culled).
  vec2 point = gl_VertexID == 0 ? start : gl_VertexID == 1 ? end : gl_VertexID == 2 ? endFar : startFar;
  if (diskCrossesLine) point = start;
  gl_Position = u_viewProjection * vec4(point, 0.0, 1.0);
  gl_Position.z = -gl_Position.w;
}
