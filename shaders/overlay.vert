#version 330 core
// The overlay's lines (the inspected pixel's rays), drawn as triangles over the picture: each
// vertex in pixels of the viewport (the picture's box; origin bottom-left) with its colour.

uniform vec2 uViewportSize; // the viewport's size in pixels

layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec3 aColour;

out vec3 vColour;

void main() {
    gl_Position = vec4(2.0 * aPosition / uViewportSize - 1.0, 0.0, 1.0);
    vColour = aColour;
}
