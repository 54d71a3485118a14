#version 330 core
// The picture's quad: two triangles covering clip space (the viewport: the picture's box),
// generated from gl_VertexID (draw 6 vertices with an empty vertex array; no attributes).

const vec2 kCorners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(1.0, 1.0),
                                 vec2(-1.0, -1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0));

void main() {
    gl_Position = vec4(kCorners[gl_VertexID], 0.0, 1.0);
}
