#version 330 core
// cnlmc AR: the contact-shadow quad on the ground plane (y = 0 of the object's frame).
in vec2 in_xz;
uniform mat4 pv_model;
uniform mat4 pv_view_projection;
uniform float pv_extent;
out vec2 v_uv;
void main() {
    v_uv = in_xz * 0.5 + 0.5;
    gl_Position = pv_view_projection * pv_model * vec4(in_xz.x * pv_extent, 0.0, in_xz.y * pv_extent, 1.0);
}
