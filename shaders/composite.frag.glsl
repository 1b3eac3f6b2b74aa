#version 300 es
// Composite pass: writes scene colour × lightmap into the host's framebuffer (alpha from the scene).
precision highp float;
precision highp sampler2D;

uniform sampler2D u_scene;
uniform sampler2D u_lightmap;

in vec2 v_uv;
out vec4 o_color;

void main() {
  vec4 scene = texture(u_scene, v_uv);
  o_color = vec4(scene.rgb * texture(u_lightmap, v_uv).rgb, scene.a);
}
