// The OpenGL entry points the renderer uses, loaded at run time through the context's
// GetProcAddress (eglGetProcAddress or OSMesaGetProcAddress; DESIGN.md section 7), so firn never
// links libGL or libOpenGL beside libOSMesa. Types and constants come from Khronos' glcorearb.h.
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace firn::viz {

// X(name, PFN type)
#define FIRN_GL_FUNCTIONS(X)                                                      \
  X(glGetString, PFNGLGETSTRINGPROC)                                              \
  X(glGetIntegerv, PFNGLGETINTEGERVPROC)                                          \
  X(glGetError, PFNGLGETERRORPROC)                                                \
  X(glViewport, PFNGLVIEWPORTPROC)                                                \
  X(glClearColor, PFNGLCLEARCOLORPROC)                                            \
  X(glClearDepth, PFNGLCLEARDEPTHPROC)                                            \
  X(glClear, PFNGLCLEARPROC)                                                      \
  X(glEnable, PFNGLENABLEPROC)                                                    \
  X(glDisable, PFNGLDISABLEPROC)                                                  \
  X(glDepthFunc, PFNGLDEPTHFUNCPROC)                                              \
  X(glDepthMask, PFNGLDEPTHMASKPROC)                                              \
  X(glReadPixels, PFNGLREADPIXELSPROC)                                            \
  X(glReadBuffer, PFNGLREADBUFFERPROC)                                            \
  X(glPixelStorei, PFNGLPIXELSTOREIPROC)                                          \
  X(glFinish, PFNGLFINISHPROC)                                                    \
  X(glGenFramebuffers, PFNGLGENFRAMEBUFFERSPROC)                                  \
  X(glDeleteFramebuffers, PFNGLDELETEFRAMEBUFFERSPROC)                            \
  X(glBindFramebuffer, PFNGLBINDFRAMEBUFFERPROC)                                  \
  X(glFramebufferTexture2D, PFNGLFRAMEBUFFERTEXTURE2DPROC)                        \
  X(glCheckFramebufferStatus, PFNGLCHECKFRAMEBUFFERSTATUSPROC)                    \
  X(glDrawBuffer, PFNGLDRAWBUFFERPROC)                                            \
  X(glDrawBuffers, PFNGLDRAWBUFFERSPROC)                                          \
  X(glGenTextures, PFNGLGENTEXTURESPROC)                                          \
  X(glDeleteTextures, PFNGLDELETETEXTURESPROC)                                    \
  X(glBindTexture, PFNGLBINDTEXTUREPROC)                                          \
  X(glActiveTexture, PFNGLACTIVETEXTUREPROC)                                      \
  X(glTexImage2D, PFNGLTEXIMAGE2DPROC)                                            \
  X(glTexParameteri, PFNGLTEXPARAMETERIPROC)                                      \
  X(glCreateShader, PFNGLCREATESHADERPROC)                                        \
  X(glShaderSource, PFNGLSHADERSOURCEPROC)                                        \
  X(glCompileShader, PFNGLCOMPILESHADERPROC)                                      \
  X(glGetShaderiv, PFNGLGETSHADERIVPROC)                                          \
  X(glGetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC)                                \
  X(glDeleteShader, PFNGLDELETESHADERPROC)                                        \
  X(glCreateProgram, PFNGLCREATEPROGRAMPROC)                                      \
  X(glAttachShader, PFNGLATTACHSHADERPROC)                                        \
  X(glLinkProgram, PFNGLLINKPROGRAMPROC)                                          \
  X(glGetProgramiv, PFNGLGETPROGRAMIVPROC)                                        \
  X(glGetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC)                              \
  X(glDeleteProgram, PFNGLDELETEPROGRAMPROC)                                      \
  X(glUseProgram, PFNGLUSEPROGRAMPROC)                                            \
  X(glGetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC)                            \
  X(glUniform1i, PFNGLUNIFORM1IPROC)                                              \
  X(glUniform1f, PFNGLUNIFORM1FPROC)                                              \
  X(glUniform2f, PFNGLUNIFORM2FPROC)                                              \
  X(glUniform2i, PFNGLUNIFORM2IPROC)                                              \
  X(glUniform3fv, PFNGLUNIFORM3FVPROC)                                            \
  X(glUniformMatrix4fv, PFNGLUNIFORMMATRIX4FVPROC)                                \
  X(glGenVertexArrays, PFNGLGENVERTEXARRAYSPROC)                                  \
  X(glDeleteVertexArrays, PFNGLDELETEVERTEXARRAYSPROC)                            \
  X(glBindVertexArray, PFNGLBINDVERTEXARRAYPROC)                                  \
  X(glGenBuffers, PFNGLGENBUFFERSPROC)                                            \
  X(glDeleteBuffers, PFNGLDELETEBUFFERSPROC)                                      \
  X(glBindBuffer, PFNGLBINDBUFFERPROC)                                            \
  X(glBufferData, PFNGLBUFFERDATAPROC)                                            \
  X(glBufferSubData, PFNGLBUFFERSUBDATAPROC)                                      \
  X(glVertexAttribPointer, PFNGLVERTEXATTRIBPOINTERPROC)                          \
  X(glEnableVertexAttribArray, PFNGLENABLEVERTEXATTRIBARRAYPROC)                  \
  X(glDisableVertexAttribArray, PFNGLDISABLEVERTEXATTRIBARRAYPROC)                \
  X(glVertexAttrib1f, PFNGLVERTEXATTRIB1FPROC)                                    \
  X(glDrawArrays, PFNGLDRAWARRAYSPROC)                                            \
  X(glDrawElements, PFNGLDRAWELEMENTSPROC)

struct Gl {
#define FIRN_GL_MEMBER(name, type) type name = nullptr;
  FIRN_GL_FUNCTIONS(FIRN_GL_MEMBER)
#undef FIRN_GL_MEMBER

  // Fills every entry through `get_proc`; throws std::runtime_error naming the first missing one.
  template <class GetProc>
  void load(GetProc get_proc) {
#define FIRN_GL_LOAD(name, type) name = reinterpret_cast<type>(get_proc(#name)), require(name != nullptr, #name);
    FIRN_GL_FUNCTIONS(FIRN_GL_LOAD)
#undef FIRN_GL_LOAD
  }

  // Throws std::runtime_error if glGetError reports an error, naming `what`.
  void check(const char* what) const;

 private:
  static void require(bool present, const char* name);
};

}  // namespace firn::viz
