#version 300 es
// Shadow mask, vertex stage: turns each shadow caster of the light into a quad (two triangles, six
// vertices, no attributes) that covers every point where the caster can hide part of the light disk.
// - A hull clear of the disk (caster -1 - its first point) casts one region: between the disk's
//   two inner tangents through the hull (the outer bounds of its penumbrae), from the hull's
//   nearest point out to the light's reach. In the umbra pass it casts its umbra instead, and for
//   the cavity stage of a concave hull its bounding box.
// - A hull close to the disk casts one quad per edge: the edge, its ends pushed along the inner
//   tangents far beyond the light's bounds (the scissor cuts them). They stay finite rather than at
//   w = 0: SwiftShader culls every triangle with a w = 0 vertex.
// All wind clockwise (y up) when the light must draw them, so light-facing edges are culled.
precision highp float;
precision highp int;
precision highp sampler2D;

// Point records: world xy, then the first point and point count of the point's hull.
uniform sampler2D u_hullPoints;
// The frame's casters (see FramePlan); this light's start at u_firstCaster.
uniform sampler2D u_casters;
uniform int u_firstCaster;
uniform mat4 u_viewProjection;
// The light: position xy, disk radius, reach (it adds nothing farther from its position). One
// vector, so that a light costs one call per program.
uniform vec4 u_light;
// Debug wireframe: eight vertices per caster, the quad's four sides as lines.
uniform bool u_outline;
// What a whole-hull caster draws: its region; its umbra, nearer the viewer (see ShadowMaskPass);
// or its bounding box (for the cavity stage).
uniform int u_shape;
const int REGION = 0;
const int UMBRA = 1;
const int BOUNDS = 2;

// Edge quads reach this many times the light's reach: far enough that even when the two tangents
// of a long edge diverge widely, the quad's far side stays outside the scissor rectangle.
const float PROJECTION_REACHES = 192.0;

vec2 lightPosition;
float lightRadius;
float lightReach;

flat out ivec2 v_hull;
// World position: the shading stages interpolate it rather than invert the view-projection per pixel.
out vec2 v_world;

#ifdef VARYING_POINTS
// For the stages of small hulls: their points, two per vector, padded with the last point. Fetched
// once per vertex here rather than once per fragment, which cost SwiftShader a third of the stage.
flat out vec4 v_points[VARYING_POINTS / 2];
#endif

vec4 texelAt(int index) {
  int width = textureSize(u_hullPoints, 0).x;
  return texelFetch(u_hullPoints, ivec2(index % width, index / width), 0);
}

float casterAt(int index) {
  int width = textureSize(u_casters, 0).x;
  return texelFetch(u_casters, ivec2(index % width, index / width), 0).r;
}

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// `direction` turned counter-clockwise by the angle of that sine and cosine.
vec2 turned(vec2 direction, float sine, float cosine) {
  return vec2(direction.x * cosine - direction.y * sine, direction.x * sine + direction.y * cosine);
}

// Corner 0..3 of an edge quad, in fan order: start, end, end projected, start projected.
vec2 edgeQuadCorner(int edge, ivec2 hull, int corner) {
  vec2 start = texelAt(edge).xy;
  vec2 end = texelAt(hull.x + (edge - hull.x + 1) % hull.y).xy;
  bool atEnd = corner == 1 || corner == 2;
  vec2 point = atEnd ? end : start;
  vec2 other = atEnd ? start : end;
  vec2 fromLight = point - lightPosition;
  float distance = max(length(fromLight), 1e-6);
  vec2 direction = fromLight / distance;
  // The inner tangent from the disk through the point leans away from the edge's other end by asin(r / d).
  float sine = min(lightRadius / distance, 1.0);
  float cosine = sqrt(1.0 - sine * sine);
  vec2 tangent = turned(direction, -sign(cross2(direction, other - point)) * sine, cosine);
  return point + tangent * (corner >= 2 ? lightReach * PROJECTION_REACHES : 0.0);
}

// Where the line through `point` along `direction` meets the line at distance `along` from the light on `axis`.
vec2 atDistance(vec2 point, vec2 direction, vec2 axis, float along) {
  return point + direction * ((along - dot(point - lightPosition, axis)) / dot(direction, axis));
}

// Corner 0..3 of a hull's region or umbra, clockwise: near and far on the high (counter-
// clockwise) line, far and near on the low one. FramePlan sends only hulls clear enough of the disk
// that all these lines lie within 78° of the axis, so the comparisons and divisions hold.
// - Region: between the inner tangents (each touches the disk on the side away from the hull's
//   touching point), the outer bounds of the penumbrae, from the hull's nearest point to the reach.
// - Umbra: between the outer tangents (disk and hull on the same side), beyond the hull's farthest
//   point, up to where they meet or the reach. The outer tangents bound a convex strip that the hull
//   crosses from side to side, so every segment from the disk to a point past the hull meets it.
vec2 hullCorner(ivec2 hull, int corner) {
  bool umbra = u_shape == UMBRA;
  vec2 highPoint, highDirection, lowPoint, lowDirection;
  float sideSign = umbra ? -1.0 : 1.0;
  // Through each point, the tangents to the disk lean asin(r / d) either side of the direction to it.
  for (int i = 0; i < hull.y; i++) {
    vec2 point = texelAt(hull.x + i).xy;
    float distance = length(point - lightPosition);
    vec2 direction = (point - lightPosition) / distance;
    float sine = min(lightRadius / distance, 1.0);
    float cosine = sqrt(1.0 - sine * sine);
    vec2 high = turned(direction, sideSign * sine, cosine);
    vec2 low = turned(direction, -sideSign * sine, cosine);
    if (i == 0 || cross2(highDirection, high) > 0.0) {
      highDirection = high;
      highPoint = point;
    }
    if (i == 0 || cross2(lowDirection, low) < 0.0) {
      lowDirection = low;
      lowPoint = point;
    }
  }
  vec2 axis = normalize(highDirection + lowDirection);
  float near = umbra ? 0.0 : lightReach;
  for (int i = 0; i < hull.y; i++) {
    float along = dot(texelAt(hull.x + i).xy - lightPosition, axis);
    near = umbra ? max(near, along) : min(near, along);
  }
  float far = lightReach;
  // Outer tangents that meet beyond the hull (a disk wider than the hull) end the umbra there.
  float meeting = cross2(highDirection, lowDirection);
  if (umbra && meeting > 0.0) {
    vec2 apex = highPoint + highDirection * (cross2(lowPoint - highPoint, lowDirection) / cross2(highDirection, lowDirection));
    far = min(far, dot(apex - lightPosition, axis));
  }
  // A region or umbra that ends before it starts collapses to a line and draws nothing.
  float along = corner == 1 || corner == 2 ? max(far, near) : near;
  return corner <= 1 ? atDistance(highPoint, highDirection, axis, along) : atDistance(lowPoint, lowDirection, axis, along);
}

// Corner 0..3 of the hull's bounding box, clockwise (y up) like the other quads.
vec2 boundsCorner(ivec2 hull, int corner) {
  vec2 low = texelAt(hull.x).xy;
  vec2 high = low;
  for (int i = 1; i < hull.y; i++) {
    vec2 point = texelAt(hull.x + i).xy;
    low = min(low, point);
    high = max(high, point);
  }
  return vec2(corner <= 1 ? low.x : high.x, corner == 0 || corner == 3 ? low.y : high.y);
}

vec2 wholeHullCorner(ivec2 hull, int corner) {
  return u_shape == BOUNDS ? boundsCorner(hull, corner) : hullCorner(hull, corner);
}

void main() {
  lightPosition = u_light.xy;
  lightRadius = u_light.z;
  lightReach = u_light.w;
  int vertex = gl_VertexID % (u_outline ? 8 : 6);
  // Triangles (0 1 2) (0 2 3), or the lines (0 1) (1 2) (2 3) (3 0).
  int corner = u_outline ? ((vertex + 1) / 2) % 4 : (vertex < 3 ? vertex : (vertex == 3 ? 0 : vertex - 2));
  float caster = casterAt(u_firstCaster + gl_VertexID / (u_outline ? 8 : 6));
  bool wholeHull = caster < 0.0;
  int point = int(wholeHull ? -1.0 - caster : caster);
  ivec2 hull = ivec2(texelAt(point).zw);
  vec2 world = wholeHull ? wholeHullCorner(hull, corner) : edgeQuadCorner(point, hull, corner);
  gl_Position = u_viewProjection * vec4(world, 0.0, 1.0);
  v_world = world;
  gl_Position.z = (u_shape == UMBRA ? -1.0 : 0.0) * gl_Position.w;
  v_hull = hull;
#ifdef VARYING_POINTS
  for (int i = 0; i < VARYING_POINTS / 2; i++) {
    v_points[i] = vec4(texelAt(hull.x + min(2 * i, hull.y - 1)).xy, texelAt(hull.x + min(2 * i + 1, hull.y - 1)).xy);
  }
#endif
}
