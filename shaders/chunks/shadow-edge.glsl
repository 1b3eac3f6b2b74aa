// Shared by the shadow-mask vertex stages: the instanced edge (one instance per hull edge, its
// number the global number of its start point) and the tangents of the light disk through its ends.
precision highp int;
precision highp sampler2D;

layout(location = 0) in uint a_edge;

// Point records: world xy, then the first point and point count of the point's hull.
uniform sampler2D u_hullPoints;
uniform mat4 u_viewProjection;
uniform vec2 u_lightPosition;
uniform float u_lightRadius;
uniform float u_projectionLength; // well beyond the light's bounds, see ShadowMaskPass

vec4 pointRecord(int index) {
  int width = textureSize(u_hullPoints, 0).x;
  return texelFetch(u_hullPoints, ivec2(index % width, index / width), 0);
}

// The edge's start and end points, and its hull's first point and point count.
void edgeOf(out vec2 start, out vec2 end, out ivec2 hull) {
  int edge = int(a_edge);
  vec4 record = pointRecord(edge);
  hull = ivec2(record.zw);
  start = record.xy;
  end = pointRecord(hull.x + (edge - hull.x + 1) % hull.y).xy;
}

// Direction, away from the light, of the line through `point` that touches the light disk: the
// light-to-point direction turned by asin(r / d), towards `other` when `towardsOther` is 1 (the
// umbra's side), away from it when -1 (the penumbra's outer side).
vec2 diskTangent(vec2 point, vec2 other, float towardsOther) {
  vec2 fromLight = point - u_lightPosition;
  float distance = max(length(fromLight), 1e-6);
  vec2 direction = fromLight / distance;
  float sine = min(u_lightRadius / distance, 1.0);
  float cosine = sqrt(1.0 - sine * sine);
  vec2 along = other - point;
  float turn = towardsOther * sign(direction.x * along.y - direction.y * along.x) * sine;
  return vec2(direction.x * cosine - direction.y * turn, direction.x * turn + direction.y * cosine);
}
