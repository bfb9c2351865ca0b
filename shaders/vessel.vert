#version 430
layout(location = 0) in vec3 in_position;  // body frame, m
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_colour;
uniform mat4 u_model;                      // body -> E frame (the 6-DOF pose)
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec3 v_colour;
out vec3 v_body;                           // body frame, m (the draft marks are painted there)
out vec3 v_body_normal;

void main() {
    vec4 world = u_model * vec4(in_position, 1.0);
    v_position = world.xyz;
    v_normal = mat3(u_model) * in_normal;
    v_colour = in_colour;
    v_body = in_position;
    v_body_normal = in_normal;
    gl_Position = u_view_projection * world;
}
