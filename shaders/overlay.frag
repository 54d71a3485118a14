#version 330 core
// The overlay's lines: one flat colour a line.

in vec3 vColour;

out vec4 fragColor;

void main() {
    fragColor = vec4(vColour, 1.0);
}
