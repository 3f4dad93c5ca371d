#version 330 core
// cnlmc preview: the environment behind the object, blurred (mip level pv_background_lod),
// drawn at 1/4 resolution (it is smooth) and upsampled bilinearly by the tone-map pass.
in vec2 v_ndc;
uniform mat4 pv_inverse_view_projection;
uniform sampler2D pv_env;
uniform float pv_env_intensity;
uniform float pv_background_lod;
out vec4 pv_color;
const float PV_PI = 3.14159265358979;

void main() {
    vec4 far = pv_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
    vec4 near = pv_inverse_view_projection * vec4(v_ndc, -1.0, 1.0);
    vec3 d = normalize(far.xyz / far.w - near.xyz / near.w);
    vec2 uv = vec2(fract(atan(d.x, -d.z) * (0.5 / PV_PI)), acos(clamp(d.y, -1.0, 1.0)) / PV_PI);
    pv_color = vec4(textureLod(pv_env, uv, pv_background_lod).rgb * pv_env_intensity, 1.0);
}
