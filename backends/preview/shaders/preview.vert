#version 330 core
// cnlmc preview: object vertices to world and clip space.
in vec3 in_position;
in vec3 in_normal;
in vec3 in_tangent;
in vec2 in_uv;

uniform mat4 pv_model;
uniform mat3 pv_normal_matrix;
uniform mat4 pv_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec3 v_tangent;
out vec2 v_uv;

void main() {
    vec4 world = pv_model * vec4(in_position, 1.0);
    v_position = world.xyz;
    v_normal = pv_normal_matrix * in_normal;
    v_tangent = mat3(pv_model) * in_tangent;
    v_uv = in_uv;
    gl_Position = pv_view_projection * world;
}
