/* gl_forward_vs.h - the vertex shader of the tests' forward programs, which
   sample shadowkit's GLSL snippet (sk_shadow(), sk_point_shadow()) per
   pixel: the testbed's world-space a_position and a_normal (locations 0 and
   1, the scene is pre-transformed) passed on as v_world and v_normal,
   v_view_depth the distance along the view axis that sk_shadow() takes,
   u_view_proj to clip space. A string literal, so that it needs no GL
   header: gl_test_util.h (gt_forward_vs, the GL tests and gl_state_app) and
   the loader tests (loader_render.h, built against GLEW and glad) share it. */
#ifndef GL_FORWARD_VS_H
#define GL_FORWARD_VS_H

#define GT_FORWARD_VS                                                  \
    "#version 330 core\n"                                              \
    "layout(location = 0) in vec3 a_position;\n"                       \
    "layout(location = 1) in vec3 a_normal;\n"                         \
    "uniform mat4 u_view_proj;\n"                                      \
    "uniform mat4 u_view;\n"                                           \
    "out vec3 v_world;\n"                                              \
    "out vec3 v_normal;\n"                                             \
    "out float v_view_depth;\n"                                        \
    "void main() {\n"                                                  \
    "    v_world = a_position;\n"                                      \
    "    v_normal = a_normal;\n"                                       \
    "    v_view_depth = -(u_view * vec4(a_position, 1.0)).z;\n"        \
    "    gl_Position = u_view_proj * vec4(a_position, 1.0);\n"         \
    "}\n"

#endif /* GL_FORWARD_VS_H */
