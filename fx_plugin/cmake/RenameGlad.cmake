# Script mode (cmake -P): RAW = glad's output folder, OUT = where the renamed loader goes.
# Renames every symbol glad defines so that it cannot collide with a host's own glad.
function(fx_rename in outfile)
  file(READ ${in} text)
  # A leading non-identifier character keeps e.g. "XGLAD_GL_" from being renamed twice.
  string(REGEX REPLACE "([^A-Za-z0-9_])glad_gl" "\\1fxglad_gl" text "${text}")
  string(REGEX REPLACE "([^A-Za-z0-9_])GLAD_GL_" "\\1FXGLAD_GL_" text "${text}")
  string(REGEX REPLACE "([^A-Za-z0-9_])gladLoadGL" "\\1fxgladLoadGL" text "${text}")
  string(REPLACE "#include <glad/gl.h>" "#include <fx_glad/gl.h>" text "${text}")
  file(WRITE ${outfile} "${text}")
endfunction()
fx_rename(${RAW}/include/glad/gl.h ${OUT}/include/fx_glad/gl.h)
fx_rename(${RAW}/src/gl.c ${OUT}/src/fx_glad.c)
file(COPY ${RAW}/include/KHR/khrplatform.h DESTINATION ${OUT}/include/KHR)
