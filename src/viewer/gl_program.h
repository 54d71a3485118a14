#pragma once
// Shader programs for the viewer's GL drawing (OpenGL 3.3 core; needs a current context with
// glad loaded).

#include <string>

namespace raylab::viewer {

// Compiles a vertex and a fragment shader and links them into a program. Returns the program's
// name, or 0 with a one-line error ("<what> does not compile: <log>" or "<what> does not link:
// <log>") after deleting whatever it made.
unsigned buildProgram(const char* vertexSource, const char* fragmentSource, const std::string& what,
                      std::string& error);

// Draws the 6 vertices of vertexArray (two triangles made by the vertex shader) with the bound
// program, `texture` on unit 0; leaves the vertex array, texture and program unbound.
void drawTexturedTriangles(unsigned vertexArray, unsigned texture);

// Deletes a drawing's GL objects; a 0 name is skipped without calling GL.
void deleteGlObjects(unsigned program, unsigned vertexArray, unsigned texture,
                     unsigned framebuffer);

} // namespace raylab::viewer
