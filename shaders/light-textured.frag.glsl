#version 300 es
// Textured light pass: adds colour × the cookie texture's red channel × visible fraction of the disk.
precision highp float;
precision highp sampler2D;
#include "light-common"

uniform sampler2D u_cookie;

void main() {
  writeLight(texture(u_cookie, v_uv).r);
}
