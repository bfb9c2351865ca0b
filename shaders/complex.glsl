// Complex numbers as vec2 (real, imaginary), for the compute shaders' spectra and transforms.

vec2 cmul(vec2 a, vec2 b) {
    return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}
