#version 330 core
// cnlmc AR: soft contact shadow, black with the footprint texture as opacity.
in vec2 v_uv;
uniform sampler2D pv_shadow;
uniform float pv_opacity;
out vec4 pv_color;
void main() {
    pv_color = vec4(0.0, 0.0, 0.0, pv_opacity * texture(pv_shadow, v_uv).r);
}
