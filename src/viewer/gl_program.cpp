#include "gl_program.h"

#include <algorithm>
#include <glad/gl.h>

namespace raylab::viewer {

namespace {

// The driver's log on one line.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') {
        text.pop_back();
    }
    return text;
}

GLuint compileShader(GLenum stage, const char* source, const std::string& what,
                     std::string& error) {
    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[1024] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        error = what + (stage == GL_VERTEX_SHADER ? " (vertex shader)" : " (fragment shader)") +
                " does not compile: " + oneLine(log);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

} // namespace

unsigned buildProgram(const char* vertexSource, const char* fragmentSource, const std::string& what,
                      std::string& error) {
    const GLuint vertex = compileShader(GL_VERTEX_SHADER, vertexSource, what, error);
    if (vertex == 0) {
        return 0;
    }
    const GLuint fragment = compileShader(GL_FRAGMENT_SHADER, fragmentSource, what, error);
    if (fragment == 0) {
        glDeleteShader(vertex);
        return 0;
    }
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[1024] = {};
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        error = what + " does not link: " + oneLine(log);
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

void drawTexturedTriangles(unsigned vertexArray, unsigned texture) {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
}

void deleteGlObjects(unsigned program, unsigned vertexArray, unsigned texture,
                     unsigned framebuffer) {
    // No GL call at all for 0 names: the context (or glad) may not exist when nothing was made.
    if (framebuffer != 0) {
        glDeleteFramebuffers(1, &framebuffer);
    }
    if (texture != 0) {
        glDeleteTextures(1, &texture);
    }
    if (vertexArray != 0) {
        glDeleteVertexArrays(1, &vertexArray);
    }
    if (program != 0) {
        glDeleteProgram(program);
    }
}

} // namespace raylab::viewer
