#version 430
// One triangle over the screen; the fragment shader turns its pixel back into a view ray.
out vec2 v_ndc;

void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    v_ndc = corner;
    gl_Position = vec4(corner, 1.0, 1.0);
}
