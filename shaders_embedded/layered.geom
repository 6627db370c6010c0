/* Layered single-pass caster rendering: every triangle arrives in world
   space (relative to the light's origin: depth.vert with SKGL_LAYERED) and
   goes to each of the skgl_layer_count layers through that layer's
   view-projection, into layer skgl_layer_of[i] of the layered depth target
   (gl_Layer: a cascade of the array texture, a face of the cube map). A
   triangle wholly outside one of a layer's clip planes skips that layer.
   With SKGL_GS_INVOCATIONS (GL_ARB_gpu_shader5) one invocation per layer;
   otherwise one invocation loops over the layers. A caster program's
   varyings (SKGL_CASTER_VARYINGS) go through skgl_caster_varyings(b, s, k)
   (defined after this source, its inputs indexed by constants only), b = s
   the vertex's unit weight, k the vertex: each vertex keeps its own values,
   a flat one included (the provoking vertex is the same either way). */
#ifdef SKGL_GS_INVOCATIONS
layout(triangles, invocations = 8) in;
layout(triangle_strip, max_vertices = 3) out;
#else
layout(triangles) in;
layout(triangle_strip, max_vertices = 24) out;
#endif
uniform mat4 skgl_layer_vp[8];
uniform int skgl_layer_of[8];
uniform int skgl_layer_count;
#ifdef SKGL_CASTER_VARYINGS
void skgl_caster_varyings(vec3 b, vec3 s, int k);
#endif

void skgl_layer(int i)
{
    vec4 c[3];
    for (int k = 0; k < 3; k++) c[k] = skgl_layer_vp[i] * gl_in[k].gl_Position;
    for (int a = 0; a < 3; a++) {
        if (c[0][a] < -c[0].w && c[1][a] < -c[1].w && c[2][a] < -c[2].w) return;
        if (c[0][a] > c[0].w && c[1][a] > c[1].w && c[2][a] > c[2].w) return;
    }
    for (int k = 0; k < 3; k++) {
#ifdef SKGL_CASTER_VARYINGS
        vec3 u = vec3(k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0);
        skgl_caster_varyings(u, u, k);
#endif
        gl_Layer = skgl_layer_of[i];
        gl_Position = c[k];
        EmitVertex();
    }
    EndPrimitive();
}

void main()
{
#ifdef SKGL_GS_INVOCATIONS
    if (gl_InvocationID < skgl_layer_count) skgl_layer(gl_InvocationID);
#else
    for (int i = 0; i < skgl_layer_count; i++) skgl_layer(i);
#endif
}
