#version 430
// A light's glow: a bright core of about two pixels and a halo that fades to the sprite's edge.
in vec3 v_colour;
in float v_strength;
in float v_size;
out vec4 f_colour;

void main() {
    float r = length(gl_PointCoord - 0.5) * 2.0;    // 0 at the centre, 1 at the edge
    if (r > 1.0) discard;
    float core = 1.0 - smoothstep(0.5 / v_size, 2.0 / v_size, r);
    float halo = pow(1.0 - r, 1.5);
    vec3 white_hot = mix(v_colour, vec3(1.0), 0.5);  // a light's centre looks whiter than its glow
    f_colour = vec4((white_hot * core + v_colour * halo) * v_strength, 1.0);
}
