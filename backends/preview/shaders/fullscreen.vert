#version 330 core
// A full-screen triangle; v_ndc in [-1, 1]^2, v_uv in [0, 1]^2.
out vec2 v_ndc;
out vec2 v_uv;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_uv = p;
    v_ndc = p * 2.0 - 1.0;
    gl_Position = vec4(v_ndc, 0.0, 1.0);
}
