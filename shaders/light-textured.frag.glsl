#version 300 es
// Textured light pass: adds colour × the cookie texture's red channel × visible fraction of the disk,
// within the light's quad (a tile of the grid over its bounds may reach past it).
precision highp float;
precision highp sampler2D;
#include "light-common"

uniform sampler2D u_cookie;

void main() {
  bool inQuad = all(greaterThanEqual(v_uv, vec2(0.0))) && all(lessThanEqual(v_uv, vec2(1.0)));
  writeLight(inQuad ? texture(u_cookie, v_uv).r : 0.0);
}
