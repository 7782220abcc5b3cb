# The plugin's private GL loader: Debian's glad2 generates a GL 3.3 compatibility-profile loader
# (a superset of core: the GL state guard pins compatibility-only state such as glAlphaFunc and
# glPixelTransferf when the host's context is a compatibility one, and calls none of them in a
# core context) plus ARB_clip_control (glClipControl) and the extensions it only checks for
# (ARB_texture_gather, ARB_gpu_shader5: FXGLAD_GL_ARB_texture_gather, ...), then every symbol it defines is renamed
# (glad_gl* -> fxglad_gl*, GLAD_GL_* -> FXGLAD_GL_*, gladLoadGL* -> fxgladLoadGL*) and the header
# moves to <fx_glad/gl.h>. A host that links its own global glad (most GL engines do) therefore
# never meets a second definition of glad_glCreateShader, in the shared library (where these are
# hidden anyway) and in the static form used by our tests alike.
# The plugin fills these pointers only through the host's getProcAddress.
#
#   fx_add_private_glad(<target> <output dir>)  -> an OBJECT library <target>, PIC, hidden
function(fx_add_private_glad target out)
  set(raw ${out}/raw)
  set(gen_h ${out}/include/fx_glad/gl.h)
  set(gen_c ${out}/src/fx_glad.c)
  add_custom_command(
    OUTPUT ${gen_c} ${gen_h} ${out}/include/KHR/khrplatform.h
    COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:compatibility=3.3
            --extensions GL_KHR_debug,GL_ARB_timer_query,GL_ARB_clip_control,GL_ARB_texture_barrier,GL_ARB_texture_gather,GL_ARB_gpu_shader5,GL_ARB_compute_shader,GL_ARB_shader_storage_buffer_object,GL_ARB_shader_image_load_store --out-path ${raw} c
    COMMAND ${CMAKE_COMMAND} -DRAW=${raw} -DOUT=${out} -P ${CUBEFX_CMAKE_DIR}/RenameGlad.cmake
    DEPENDS ${CUBEFX_CMAKE_DIR}/RenameGlad.cmake
    COMMENT "Generating the plugin's private GL 3.3 loader (glad, renamed fxglad_)"
    VERBATIM)
  add_library(${target} OBJECT ${gen_c})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${out}/include>)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON
                        C_VISIBILITY_PRESET hidden)
endfunction()
