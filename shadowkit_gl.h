/* shadowkit_gl.h - v0.1.0 - public domain / MIT - OpenGL 3.3 core shadow passes

   The GPU half of shadowkit: depth passes, cascade selection, filtering and
   the deferred shadow mask, driven by the math in shadowkit.h. Owns its GL
   objects, never your scene.

   USAGE
     In exactly one C or C++ file, after your GL loader (or none at all):
         #define SHADOWKIT_IMPLEMENTATION
         #define SHADOWKIT_GL_IMPLEMENTATION
         #include "shadowkit_gl.h"          (includes shadowkit.h)
     No system GL header is needed: the ~90 entry points shadowkit uses are
     loaded into a private table through the getproc function you pass
     (glfwGetProcAddress, eglGetProcAddress, OSMesaGetProcAddress...), so it
     coexists with glad, GLEW or anything else.

   CONFIGURATION (define before the #include that has the implementation)
     shadowkit.h's own (SK_ASSERT, the math functions, SKDEF,
     SHADOWKIT_STATIC: its USAGE), and:
         SHADOWKIT_GL_IMPLEMENTATION  the implementation in this file (with
                                SHADOWKIT_IMPLEMENTATION in the same file)
         SKGLDEF                default SKDEF: extern, or static with
                                SHADOWKIT_STATIC
         SKGL_MALLOC(n), SKGL_FREE(p)   default malloc and free; define
                                both or neither (one alone is an #error)
         SKGL_ORIGIN_CELL       default 256.0: the grid the directional
                                passes' origin snaps to (LARGE WORLDS);
                                <= 0 keeps the world origin
         SKGL_LAYERED_LOOP      defined: the layered passes always use the
                                GL 3.3 core geometry shader that loops over
                                the layers, never the instanced one of
                                GL_ARB_gpu_shader5 (what a driver without
                                the extension runs; LAYERED PASSES)
         SKGL__APIENTRY         the calling convention of the loaded GL
                                entry points; default __stdcall on _WIN32,
                                nothing elsewhere
         SKGL_NO_SOFT           defined: the area lights (skgl_soft_*,
                                PCSS and PVSM) and their shaders are left
                                out; the declarations stay, skgl_soft_create
                                and skgl_soft_render return
                                SK_ERR_INVALID_ARG with "...: compiled out
                                (SKGL_NO_SOFT)" in skgl_error_log, the
                                accessors answer as for NULL;
                                skgl_area_light_axes stays
         SKGL_NO_RMSM           defined: SKGL_RMSM (virtual shadow map
                                pages, their cache and the context's two
                                RMSM programs) is left out; a shadow
                                created with technique SKGL_RMSM fails
                                with SK_ERR_INVALID_ARG, "... compiled out
                                (SKGL_NO_RMSM)"; skgl_shadow_pages and
                                skgl_shadow_analysis_texture answer 0
         SKGL_NO_CACHE          defined: cached maps (CACHED MAPS: the
                                static casters' copies of directional
                                layers, RMSM pages, point faces and spots,
                                their scrolls, region redraws and
                                .verify_cache read-backs) are left out; a
                                desc with .cache 1 (skgl_shadow_create,
                                skgl_point_create) fails with
                                SK_ERR_INVALID_ARG, "...: desc.cache = 1:
                                cached maps are compiled out
                                (SKGL_NO_CACHE)"; skgl_shadow_invalidate
                                and skgl_point_invalidate check their
                                arguments and return SK_OK, as for a light
                                without a cache (nothing to redraw);
                                skgl_set_dynamic stays (its casters are
                                drawn in every pass)
         SKGL_NO_CASTERS        defined: caster programs (CASTER PROGRAMS)
                                are left out; skgl_caster_create returns
                                SK_ERR_INVALID_ARG with "skgl_caster_create:
                                compiled out (SKGL_NO_CASTERS)" and *out
                                NULL, skgl_use_caster returns NULL with
                                "skgl_use_caster: compiled out
                                (SKGL_NO_CASTERS)" (in a draw callback the
                                render then fails with SK_ERR_INVALID_ARG),
                                skgl_caster_destroy does nothing. Neither
                                switch has shaders of its own to remove:
                                the cache copies depth with blits, and a
                                caster's hooks replace parts of depth.vert
                                and depth.frag, which every light uses
         SKGL_NO_FERKO          defined: the depth buffer's analysis
                                (6.3: the G-buffer reductions of
                                ferko_analyze.frag and ferko_reduce.frag,
                                their three programs and read-back ring)
                                and everything that reads it are left
                                out: SKGL_FERKO, SKGL_AUTO (CHOOSING FOR
                                YOU: it splits the depth range the
                                analysis measures) and .fit_to_depth. A
                                light asking for one fails with
                                SK_ERR_INVALID_ARG, "skgl_shadow_create:
                                desc.technique = 5: FERKO's resolution
                                estimation is compiled out
                                (SKGL_NO_FERKO)", "... desc.technique =
                                7: AUTO splits the depth range of the
                                depth analysis, which is compiled out
                                (SKGL_NO_FERKO)" or "... desc.fit_to_depth
                                = 1: the depth analysis is compiled out
                                (SKGL_NO_FERKO)". The three share one
                                analysis: keeping it for AUTO and
                                .fit_to_depth would leave out only
                                FERKO's estimate and crop fit, about 60
                                of the 405 lines this switch removes.
                                skgl_shadow_analyze then serves RMSM
                                alone. With all five switches what stays
                                is STANDARD, PSSM, PSM, LiSPSM and LSPSM,
                                point and spot lights, the atlas and EVSM
     Nothing else is read from the preprocessor: the rest is chosen at run
     time through the descs.

   THE FLOW (one directional light, every frame)

       skgl_context *gl;                 once: skgl_create(&desc, &gl)
       skgl_shadow *sun;                 once: skgl_shadow_create(gl, &sdesc, &sun)

       skgl_camera cam = { view, proj };
       skgl_scene scene = { draw_casters, my_user_ptr, scene_bounds };
       skgl_shadow_render(gl, sun, &cam, &scene, light_dir);
       then either
         skgl_shadow_mask(gl, sun, &cam, depth_tex, normal_tex, mask_tex);
           (deferred: R16F visibility per pixel, 1 lit .. 0 shadowed)
       or, in your own forward shader that pastes skgl_glsl_snippet():
         glUseProgram(prog); skgl_shadow_bind(gl, sun, prog, unit);
         ... in GLSL: float v = sk_shadow(world_pos, world_normal, view_depth);

       skgl_shadow_destroy(gl, sun); skgl_destroy(gl);   at shutdown

   SCENE ACCESS
     shadowkit asks only for a draw callback and the scene's bounds: a box
     around every caster and receiver. The bounds pull the light's near
     plane back so that off-screen casters still cast, and they also clip
     the fitted maps (a focused crop covers the view inside the bounds
     only) and end the shadow range where the scene ends: what lies outside
     them gets no shadow. Zero (a point), inverted or non-finite bounds,
     or a coordinate beyond 1e18, are refused (SK_ERR_INVALID_ARG naming
     scene->bounds) by every render and analysis. For
     each shadow pass it binds its depth program (attribute 0 = position,
     vec3) and calls draw(user, info): bind your VAOs and draw the casters;
     call skgl_set_model(gl, matrix) before an object whose model matrix is
     not the identity. info gives the pass's view-projection, its kind and
     index (cascade) and its frustum, so you can cull.
     A pass of several layers, faces or pages binds its program and sets
     the identity model once, before the first callback; after a callback
     that called skgl_set_model it sets the identity again. So the callback
     may change: the model (skgl_set_model), the vertex array, buffer
     bindings (pixel pack and unpack buffers included), texture bindings,
     the active texture unit and sampler bindings (the depth program
     samples nothing), culling (glEnable(GL_CULL_FACE), glCullFace: single-
     sided casters; shadowkit's passes draw both faces otherwise), the
     caster program (skgl_use_caster, CASTER PROGRAMS) and its uniforms,
     and the current program, if it binds info->program again before it
     returns (then it sets its own view-projection from info->view_proj,
     and a large world's origin and PSM's warp are its own to get right:
     caster programs are the way that needs neither). Everything else
     it must leave as it found it: the framebuffer, viewport, scissor,
     depth test, function, writes and clamping, polygon offset and mode,
     blending and the colour mask. With desc.debug each of those shadowkit
     set, and the program, is checked after each callback: a change gets
     SK_ERR_INVALID_ARG, and skgl_error_log names what changed. The default
     mode puts the caller's vertex array and culling back after the passes.

   CASTER PROGRAMS (skgl_caster_*: skinning, wind, instancing, alpha tests)
     Casters whose vertices are not a vec3 at attribute 0 times a model
     matrix, or that discard fragments, give shadowkit a hook once:

         skgl_caster_desc cd = {0};
         cd.vertex =
             "layout(location = 0) in vec3 a_pos;\n"
             "layout(location = 1) in vec2 a_uv;\n"
             "layout(location = 2) in vec4 a_offset;       // per instance\n"
             "uniform float u_time;\n"
             "vec4 skgl_caster_position() {\n"
             "    v_uv = a_uv;\n"
             "    vec3 p = a_pos + a_offset.xyz;\n"
             "    p.x += 0.1 * sin(u_time + p.y);            // wind\n"
             "    return vec4(p, 1.0);\n"
             "}\n";
         cd.fragment = "uniform sampler2D u_leaf;\n"
                       "void skgl_caster_fragment() {\n"
                       "    if (texture(u_leaf, v_uv).a < 0.5) discard;\n"
                       "}\n";
         cd.varyings = "vec2 v_uv;";
         cd.uniforms[0] = "u_time"; cd.uniforms[1] = "u_leaf";
         skgl_caster_create(gl, &cd, &foliage);

     and select it in the draw callback, per object, then set its uniforms
     with the program bound:

         const int *loc = skgl_use_caster(gl, foliage);
         if (loc) {
             glUniform1f(loc[0], time); glUniform1i(loc[1], 4);   // leaf texture on unit 4
             skgl_set_model(gl, tree_model);
             glBindVertexArray(tree_vao);
             glDrawElementsInstanced(...);
         }
         skgl_use_caster(gl, NULL);          // shadowkit's own program again

     skgl_caster_position() returns the vertex in the space the model
     matrix (skgl_set_model, the identity by default) takes to the world;
     shadowkit applies the model, a large world's origin and the pass's
     view-projection (PSM's post-perspective space, a cube face, a page)
     itself, so one hook serves every technique. shadowkit links the hook
     into each kind of caster pass the first time it is needed: the depth
     passes (every directional map, cube faces, the VSDCT atlas, PCSS's map,
     PVSM's tiles; linked by skgl_caster_create), PVSM's conservative
     low-resolution pass (through its geometry shader, which carries the
     varyings to the grown triangle's corners, perspective-correct) and the
     area lights' own G-buffer. SKGL_CASTER_PASS is 0, 1 or 2 in those, for
     hooks that differ (SKGL_LAYERED is defined in the layered passes). The
     hooks are GLSL 3.30 without #version or #extension lines; they may
     declare anything but main and the names starting with skgl_ or SKGL_,
     which shadowkit's passes use for all of their own (a hook's #define
     holds within that hook: shadowkit #undefs each after it):
     skgl_view_proj, skgl_model, skgl_texel, skgl_conservative, skgl_eye,
     skgl_layer_vp, skgl_layer_of, skgl_layer_count (uniforms),
     skgl_world, skgl_box, skgl_edge, skgl_caster_block, skgl_in, skgl_out
     (between stages), skgl_cons, skgl_true, skgl_cons_copy, skgl_normal
     (outputs), skgl_caster_varyings, skgl_layer, skgl_w, skgl_n, skgl_p,
     skgl_inside (functions and locals after the hooks) and the macros
     SKGL_CASTER, SKGL_CASTER_PASS, SKGL_CASTER_FRAGMENT, SKGL_CASTER_VARYINGS,
     SKGL_LAYERED and SKGL_GS_INVOCATIONS.
     desc.varyings is a list of declarations `[qualifiers] type name;`,
     qualifiers among flat, smooth, noperspective (not in GLSL ES: the
     compiler refuses it there; #ifndef GL_ES keeps it out), centroid and
     a precision, one name each (no lists, no arrays), at most
     16; line (//) and block comments, and #if, #ifdef, #ifndef, #elif, #else,
     #endif, #define and #undef lines between declarations are kept (each
     stage sees the same; a #define holds within desc.varyings only), any
     other line is refused with its line named. shadowkit declares them in
     each stage (an interface block where a geometry shader runs), so they
     need no in/out of their own and are written and read by name; the
     geometry shaders give every vertex they emit the values the original
     triangle has there (perspective-correct, or linear in the window for
     noperspective); a flat varying keeps each vertex's value in the
     layered passes (the provoking vertex chooses as without them) and
     takes the last vertex's, GL's default provoking vertex, on PVSM's
     grown triangles. Errors in a declaration's type are reported at line
     20000 + its line.
     Textures the fragment hook samples go on units 4 and up: shadowkit's
     passes bind their own samplers on units 0 to 3. Compile errors are
     returned by skgl_caster_create (or, for the two later programs, by the
     render that first needs them) with the driver's message, its line
     numbers the hook's own. Each program sends the pass's matrix once per
     callback, the model as the identity at every skgl_use_caster; after the
     callback shadowkit's own program is current again.

   LAYERED PASSES (skgl_shadow_desc.layered, skgl_point_desc.layered)
     A light of several layers (PSSM, LSPSM, LiSPSM with cascades, a cube
     map's faces) calls the callback once per layer by default. With
     .layered = 1 it calls it once: what it draws goes to every layer
     through a geometry shader that sends each triangle to each layer's
     matrix and writes gl_Layer (one invocation per layer with
     GL_ARB_gpu_shader5, a loop otherwise; both GL 3.3 core). info->layers
     is then the number of layers, info->index -1, and
     info->layer_view_proj[i] / layer_frustum[i] / layer_index[i] each
     layer's matrix, frustum and cascade or face: cull against any of them
     (skgl_point_caster_visible does). A caster program gets its layered
     version the same way. The maps are the same as with a pass per layer;
     the draw calls are divided by the layers, the geometry shader's cost
     added: time both on your GPU (the stats' layered field says which ran).
     RMSM draws its pages SKGL_MAX_CASCADES at a pass: each into a layer of
     a page-sized array target, then copied into its pool slot as a pass
     per page does; layer_index[i] is then the page (skgl_shadow_pages'
     order), its depth the per-page one but for the last bits (a cached
     RMSM light, refused with .layered, draws a pass per page). On
     llvmpipe, tests/gl/test_gl_open_world.c's 2 km views (one draw of the
     whole scene a callback, 30 frames): 188 pages a frame at 16384^2 in
     24 callbacks, 479 at 65536^2 in 60; the render 216 -> 175 ms and 398
     -> 359 ms through the geometry shader's loop (SKGL_LAYERED_LOOP), but
     4.2x and 4.8x slower than a pass per page through llvmpipe's
     invocations; on ground-boxes (572 pages) 0.65-0.83x either way. VSDCT's
     atlas and one-map techniques keep one pass each.

   CACHED MAPS (skgl_shadow_desc.cache, skgl_point_desc.cache)
     Most casters do not move from one frame to the next. A cached light
     keeps the depth of the casters scene.draw draws and redraws only what
     changed. The model asks three things of the scene:
       1. What moves is drawn by a second callback, skgl_set_dynamic(gl,
          &dyn) (skgl_dynamic: draw, user, bounds): characters, doors,
          wind-swayed foliage, anything animated. It is drawn every frame,
          over a copy of the cached depth, and needs no invalidation. Give
          dyn.bounds (a box around them this frame) and only the texels it
          covers are drawn, and last frame's copied back.
       2. When something scene.draw draws changes (a static caster moved
          once, appeared, went), say where: skgl_shadow_invalidate(gl,
          sun, &box) / skgl_point_invalidate(gl, lamp, &box) with the world
          box it left and the one it came to. The texels those boxes cover
          are drawn again at the next render. box NULL: everything.
       3. Nothing else. A change of the light, of the map's crop or warp,
          of the scene's bounds or of the face side is seen by shadowkit
          itself: each cached layer keeps the matrix it was drawn with and
          is drawn whole when the new one differs. A stable crop (.stable
          = 1) that follows the camera by whole texels is scrolled: the
          overlap copied, only the strips it exposes drawn. The
          comparison is with the matrix the layer was drawn with, not
          last frame's: a change too small to see in one frame (a sun
          turning 5e-7 rad a frame, a camera creeping under a focused
          crop) is allowed to add up to 1e-3 texel (1e-6 in depth), then
          the layer is drawn again. A kept layer's strips, regions and
          dynamic casters are drawn with its own matrix, so it stays one
          map; the lookup uses this frame's.

         skgl_scene scene = {draw_static, me, bounds};
         skgl_dynamic movers = {draw_movers, me, movers_box};
         sdesc.technique = SKGL_PSSM; sdesc.stable = 1; sdesc.cache = 1;
         ...
         skgl_set_dynamic(gl, &movers);      (each frame, as they move)
         if (door_moved) {
             skgl_shadow_invalidate(gl, sun, &door_box_before);
             skgl_shadow_invalidate(gl, sun, &door_box_now);
         }
         skgl_shadow_render(gl, sun, &cam, &scene, light_dir);

     What is reused: a cascade whose crop did not move renders only the
     dynamic casters; a stable cascade that moved draws its new strips; a
     focused crop or a LiSPSM/PSM/LSPSM warp follows the camera and is
     drawn whole whenever the camera moves (reused while it stands still):
     cache stable maps. A point light's faces are kept while the light
     stays where it was at the same face side; its caster culling then
     keeps every static caster a face can see, whatever the view, and culls
     only the dynamic ones by the view. A spot's map is kept while its
     matrix (position, direction, window) and side stay (SPOT LIGHTS). RMSM keeps pages: its virtual
     map's texel grid is fixed in light space (the scene's bounds and the
     light alone place it, not the camera), so a page keeps its depth from
     frame to frame. Every page is drawn at the same place of a one-page
     target and copied into its pool slot (the rasterizer's depth depends
     in its last bits on the window position), so a page holds the same
     depth in any slot: cached and uncached pages are equal bit for bit.
     A page stays in its pool slot while it is requested
     and after, until a new page needs the slot (least recently used
     first); only pages that came into view, or that an invalidated box or
     a new light emptied, are drawn (stats pages_rendered, pages_reused,
     pages_evicted, pages_resident; cache_regions counts the pages boxes
     emptied). The dynamic casters are drawn over the static depth of the
     pages their bounds touch, restored the next frame from a static copy
     of the pool. Not cached: FERKO (its crop and size follow the
     G-buffer), layered passes and shared atlases (refused at create,
     naming desc.cache).
     A cached stable crop's depth range is the scene's bounds in light
     space (the sphere's would move with the camera): set tight bounds.
     The callbacks' info->rect is the texel rectangle a pass draws (an
     exposed strip, an invalidated region; all 0: the whole map), for
     callbacks that cull finely; info->dynamic says which callback runs.
     Memory: one depth texture the size of the light's maps (stats
     cache_bytes); .cache_budget_kb caps it: a directional light caches
     its nearest layers while they fit and draws the rest every frame, a
     point light whose cache does not fit is drawn every frame. RMSM's
     pages live in its pool (rmsm_pool_pages caps them); its cache takes
     GPU memory only for the static copy of the pool, made when dynamic
     casters first come: over the budget there is none, and the pages
     they touch are drawn whole each frame instead. Misuse is
     caught with .verify_cache = 1 (skgl_shadow_desc and skgl_point_desc;
     desktop GL, a debugging aid: every cached layer, RMSM page or point
     face the frame uses is also drawn uncached, with the matrix the cached
     one stands for, and both read back, a stall). Texels whose depths
     differ by up to 1e-5 are equal (a scrolled overlap's rounding, up to
     2.8e-6 measured); a differing texel with no differing neighbour is an
     edge a scroll's float rounding moved across a texel centre, accepted;
     differing texels side by side are a change the cache was not told of:
     more than 1e-5 of a layer's (face's, the pages') texels so fail the
     render with SK_ERR_INVALID_ARG, the log naming the layer (face, page),
     what the cache did with it this frame (drawn whole, scrolled by how
     many texels, reused), how far the depths differ, the texels side by
     side and alone, and the likely cause (a caster scene.draw draws moved
     without an invalidation); stats.cache_verify_texels counts the texels
     side by side.

   TECHNIQUES (skgl_shadow_desc.technique)
     SKGL_STANDARD  one focused map: the view frustum clipped to the scene
                    bounds, fitted in light space (Ferko 2013's crop, Brabec);
                    .stable = 1 snaps it to whole texels (no shimmer).
     SKGL_PSSM      parallel-split cascades with the practical split scheme
                    (Romanick's VGP353 notes), one layer of a depth texture array each,
                    per-cascade crop (or stable crop), cascade chosen per
                    pixel by view depth, optional blend band.
     SKGL_PSM       perspective shadow map (Stamminger & Drettakis 2002):
                    rendered in the camera's post-perspective space, fitted
                    to the receivers there; .psm_slide moves the virtual
                    camera back by that many sqrt(near*far) [0.5] for more
                    uniform texels. A light behind the viewer reverses the
                    depth order: the map's z is negated, so nothing changes
                    for you (stats.depth_reversed says it happened).
                    Casters behind the camera slide the virtual camera back;
                    the casters are those that can shadow what the view
                    sees (each receiver point and where its ray toward the
                    light leaves scene.bounds), not the whole scene, so a
                    kilometre of scene behind the camera does not make the
                    map uniform (stats.psm_slide says how far it slid).
     SKGL_LISPSM    light-space perspective shadow map (Wimmer et al.) with
                    n_opt; fades into the focused map as the light turns
                    parallel to the view (stats.warped, stats.warp_n).
                    .cascades > 1: one LiSPSM per PSSM cascade.
     SKGL_LSPSM     light space partitioned maps (Tang et al. 2017): the
                    view's trapezoid on the light plane cut by Eq. (1), one
                    layer per partition (.lspsm: zeta, sigma, h_max, nw_max;
                    stats.maps = partitions), the partition picked per pixel.
     SKGL_FERKO     one map whose crop and size come from the camera's depth
                    buffer (Ferko 2013): call skgl_shadow_analyze()
                    first; .resolution is the largest size it may take.
                    By default the estimate comes back through the
                    read-back ring (READ-BACKS) and is used a frame
                    later: no CPU-GPU stall, but fast motion can clip
                    the crop; .sync_readback = 1 uses this frame's.
     SKGL_RMSM      a virtual map (.resolution, 16384 by default) of pages
                    (.rmsm_page_size) rendered only where the view needs them,
                    at the level of detail it needs (Romanick's VGP353 notes;
                    a page's texel matches the narrow side of the pixel's
                    footprint in the map, so grazing receivers far away
                    get pages as fine as their shadow edges need): call
                    skgl_shadow_analyze() first; pages live in a pool of
                    .rmsm_pool_pages^2 slots, found through a page table
                    (texture unit `unit` + 1 in skgl_shadow_bind). The page
                    requests come back through the read-back ring: the
                    pages of the last frame's requests are rendered (by
                    default; .sync_readback = 1: this frame's); where a
                    page is missing the lookup falls back
                    to a coarser resident one. Where the pool holds them
                    (.rmsm_band_pages, stats.rmsm_band) the pages go no
                    coarser than a world size, the finest the pool holds,
                    and a level finer than the pixel where it holds that
                    too (stats.rmsm_band_finer): a texel matched to a
                    pixel misses casters thinner than the pixel (a pole
                    at 500 m).
     SKGL_AUTO      the library chooses (CHOOSING FOR YOU): one map or 2 to
                    .cascades cascades, focused (STANDARD, PSSM) or warped
                    (LiSPSM), per frame, from the view's depth range and the
                    scene; call skgl_shadow_analyze() first, as for FERKO.
     Focused crops end the shadow range where the scene ends and fit the view
     clipped to the scene. .fit_to_depth (STANDARD, PSSM, LiSPSM) also starts
     and ends it at the view depths the depth buffer holds (sample
     distribution shadow maps, Lauritzen, Salvi and Lefohn 2011), through
     skgl_shadow_analyze and its read-back ring: the splits follow what is
     visible instead of the near plane. With .lambda left 0 they are
     logarithmic over an analysed range, as the paper's (.lambda's 0.75
     before the first analysis): the range starts at the nearest receiver,
     where the practical scheme's uniform term only lengthens the first
     cascade (open world, PSSM 4 x 1024^2: 1.03% against 1.70% at 0.75
     and 1.77% unfitted).

   STABLE CROPS (.stable = 1)
     Each crop's width and height step on a fixed ladder, 2^(k/8) world units
     (9% steps), at least the focused crop's, and its corner snaps to whole
     texels of a grid fixed in world light space; the shadow range ends at a
     ladder step at or past the scene's far side. As the camera moves a
     little nothing changes size and the crop moves by whole texels: no
     shimmer. A size changes only when the view's need crosses a step; it
     shrinks at once when the need falls six steps (a factor 1.68) below
     it, and after 60 renders in a row two or more steps below, so a
     wavering need does not resize back and forth and a need that has
     fallen for good gets its smaller crop (and at once when the shadow
     range's end steps, which moves every split). A camera cut (turned more than
     about 30 degrees, or moved farther than the first crop's smaller side,
     since the last render) starts every size afresh. Measured: a camera
     turning 120 degrees resizes a layer in 14 of 119 frames, walking 30 m
     in 8; the error is 0.84 to 1.11x the focused crop's (0.93x in the open
     world). .stable_sphere = 1, and every cached light (.cache: a cached
     layer is drawn whole again whenever its crop changes size), bounds each
     cascade by a sphere that depends only on the camera's projection and
     the split distances, over [near, max_distance or far]: the texel size
     never changes however the camera turns, at the price of covering more
     than the view needs (1.77x the focused error in the open world, up to
     3.6x on small scenes; set max_distance).

   CHOOSING FOR YOU (SKGL_AUTO)
     You give a texel budget, .resolution^2 texels a frame [2048^2], and a
     target, .auto_texel_px: how many pixels one shadow texel may span [1].
     Each frame, for 1 to .cascades [4] maps sharing the budget (side
     .resolution / sqrt(n)), AUTO splits the view depths the analysis found
     (as .fit_to_depth) with the logarithmic scheme (lambda 1: over a range
     that starts at the nearest receiver seen, the log splits spread the
     perspective aliasing evenly; Zhang, Sun, Xu and Lun 2006's uniform
     term only helps a near plane in front of every receiver, so .lambda
     [0.75] serves before the first analysis), fits each count's crops once
     and predicts the texel-to-pixel ratio at the near end of each map (the
     crop's larger side over the map's side, against a pixel's footprint
     there, 2 d tan(fovy/2) / the analysed depth buffer's height). It
     also warps each count's slices (a LiSPSM per slice, Wimmer, Scherzer
     and Purgathofer 2004, as SKGL_LISPSM with .cascades n) and predicts
     their ratio from the warp itself: the map's Jacobian across the light
     at four depths of each slice along the view's axis, the worst of them
     (a warp spreads its texels over the slice). A small range needs fewer
     maps: it takes the fewest maps whose worst ratio meets the target
     (of a focused and a warped set of that count, the smaller ratio),
     else the fewest maps within 25% of the smallest ratio (a map more
     costs a caster pass; from a set in use that misses the target, fewer
     maps only when at most 9% coarser). The set in use is kept unless
     the new one is 15% better, has fewer maps and meets 0.85 of the
     target, or the old misses the target by 15% and the new one meets it
     (hysteresis: a camera bobbing about the height where the choice
     changes keeps it; the first analysed range picks afresh).
     stats.maps, stats.auto_technique (SKGL_STANDARD, SKGL_PSSM, or
     SKGL_LISPSM when warped; stats.warped and stats.warp_n per map),
     stats.auto_lambda, stats.auto_texel_px and
     .auto_texel_px_warped (the prediction for each count) and
     stats.auto_reason (in words) say what it chose and why. A warp pays
     where the view looks along the ground: test_gl_auto's low views of
     small scenes 3.04% against 5.90% focused, the open world with 2 warped
     maps instead of 4 cascades in a third of its frames (1.12% against
     1.03%). .disable_auto_warp = 1 keeps to focused maps. Not with
     .stable or .cache (the splits follow the depth buffer).
     The analysis runs only when the range may have changed: the first
     call, a new G-buffer size or projection, the camera moved more than 5%
     of the nearest depth measured or turned more than about 1.7 degrees,
     and every 8th call whatever the camera did (moving objects); otherwise
     skgl_shadow_analyze keeps the last range and does no GL work
     (stats.auto_analysed 0, analysis_ms 0).
     Memory: the chosen count's n layers of (.resolution / sqrt(n))^2
     depth texels (32-bit float), about .resolution^2 x 4 bytes whatever n:
     16 MiB at the defaults (4 x 1024^2 or 1 x 2048^2; 3 x 1182^2, 2 x
     1448^2). When the count changes to one the texture cannot hold, it
     grows at once to hold both counts (at most .cascades x .resolution^2 x
     4 bytes, 64 MiB, while the choice moves), and shrinks to the count's
     exact size once a count has been kept for 30 renders: a camera moving
     between two counts re-allocates at most twice per 30 frames.
     stats.auto_bytes says what it holds.
     Why not PSM, LSPSM or virtual maps: PSM's single warp and LSPSM's
     partitions err more than cascades at equal texels in the open world
     (a light along the view, casters behind the camera), and RMSM's page
     passes cost far more time; a small scene seen whole is best served by
     one focused map.

   POINT LIGHTS (skgl_point_*, King & Newhall 2004; the flow is in the declarations)
     SKGL_POINT_CUBE   a GL depth cube map, samplerCubeShadow.
     SKGL_POINT_VSDCT  the six faces in one 2D depth atlas and an RG16
                       indirection cube map (Virtual Shadow Depth Cube Texture).
     Both store window depth per Eq. (5.4.6) and compare the same way. Face
     culling, caster culling (skgl_point_caster_visible in the callback),
     the scissored mask and resolution selection are switches in
     skgl_point_desc, off by default (the naive cube map).
     Several VSDCT lights may share one atlas (skgl_point_atlas_create,
     desc.atlas): skgl_point_atlas_pack places every light's six faces at
     its selected side each frame, halving the largest side until they fit.

   SPOT LIGHTS (a skgl_point with desc.spot_angle > 0; skgl_spot_render)
     One perspective map from the light down its direction, in a 2D depth
     texture of .resolution^2 (VSDCT's storage; its side selected by King
     and Newhall's N M^2 >= c S with N = 1 under .select_resolution). The
     map's window is the cone's square clipped to the rectangle that the
     scene's bounds inside the view frustum cover beyond the near plane,
     grown by the filter's reach and snapped (sk_spot_window): its side a
     power-of-two fraction of the cone's, its corner on that side's texel
     grid, so texels stay put while the window follows the view, and a
     cone wider than what the view sees spends its texels there. Depth and
     both biases are the point light's (Eq. 5.4.6 with MA the depth along
     the axis). Caster culling (.cull_casters, skgl_point_caster_visible
     in a SKGL_PASS_SPOT callback) by the cone (sk_spot_box_visible) and
     by the caster's shadow against the view; the mask's scissor, and the
     S of the selection, are those of the box around the cone's bounding
     sphere. The mask and sk_point_shadow give 0 outside the cone.
     Spots share a point-light atlas (desc.atlas): skgl_point_atlas_pack
     places a spot's one face beside the point lights' six, at its
     selected side (for S, the direction of its last render; the range
     sphere before the first). Not with .layered. Cached (.cache, CACHED
     MAPS) as a point light's faces: the map's static depth is kept while
     the light's matrix (position, direction, the snapped window) and the
     side stay as they were, redrawn where skgl_point_invalidate says,
     the dynamic casters drawn over a copy; a view that changes the window
     (it sees another part of the cone) draws it whole. A cached spot's
     caster culling keeps every static caster in the cone, whatever the
     view. Not cached in a shared atlas (as point lights).

   AREA LIGHTS (skgl_soft_*, Shen et al. 2011; the flow is in the declarations)
     SKGL_SOFT_PCSS    percentage-closer soft shadows on one map.
     SKGL_SOFT_PVSM    predicted virtual soft shadow maps: a conservative
                       low-resolution map, a kernel per pixel, the predicted
                       resolution gathered in a tile grid, one map per tile
                       at that resolution, smooth texel-coverage filtering.
     A rectangle light at a position (skgl_area_light), deferred: depth and
     normals in (or rendered by shadowkit), visibility out, in one call.
     Each of PVSM's steps is timed (stats.step_ms); skgl_soft_tiles() lists
     the tiles for a debug view.

   BIAS AND FILTERING
     The default (.bias = SKGL_BIAS_RECEIVER_PLANE, directional and point
     lights) keeps a receiver out of its own shadow without moving it: each
     texel the filter reads is compared with the depth that the receiver's
     tangent plane has at that texel's centre (Dou et al. 2014), less
     .plane_bias texels of the plane's own depth slope. A flat receiver gets
     no acne at any light elevation, and no shadow edge is displaced. The
     plane comes from the normal you pass (the G-buffer normal in the mask
     pass); with a zero normal, from the screen derivatives of the position
     (Isidoro 2006), so call sk_shadow() in uniform control flow. Point
     lights compare the plane's depth along each hardware tap, less the
     plane's change over the one texel a 2x2 comparison reaches.
     SKGL_BIAS_NORMAL_OFFSET is the classic scheme: receivers pushed along
     their normal by .normal_bias texels of their map (warped maps have
     texels of varying size); it moves every shadow edge toward the light by
     about .normal_bias texels times the cotangent of the light's elevation
     (10 texels at 8 degrees). In both, casters are drawn with slope-scaled
     polygon offset (.slope_bias, in depth slope units, i.e. texels).
     The filter (directional lights) is a box over the map's texels, each
     texel weighed by the part of the box it covers. Its size, the half-width:
       .filter_world  in world units, measured across the light's direction:
                      the same penumbra in every cascade, at every map
                      resolution and in every technique (test_gl_filter_world:
                      10-90% widths within 0.3% over 3 PSSM cascades and 2
                      resolutions; STANDARD, PSM, LiSPSM, LSPSM and FERKO
                      within 5% of them).
                      The shader divides it by the world size of the texels
                      of the point's layer, per map axis (a warped map's
                      change across the view), and keeps the result in
                      [1/2, 8] texels: a radius past 8 texels of a fine
                      cascade is cut to 8 there (its penumbra narrower than
                      asked for), one under half a texel is the one 2x2
                      comparison. RMSM: always one 2x2 comparison (its pages'
                      borders are one texel). A constant world width, not a
                      sun's angular size: for penumbrae that widen with the
                      distance to the caster, see the area lights (PCSS).
       .pcf_radius    r texels, when .filter_world is 0 (the default, 1);
                      .disable_pcf_kernel: the one 2x2 comparison (radius 1/2).
     With the normal offset (or no bias) the box's texels are taken two by
     two along each axis in hardware 2x2 comparisons placed between them in
     the ratio of their weights (Castano 2013, "Shadow Mapping Summary - Part
     1"): a radius of R texels reads (ceil(2R)+1)^2 texels in
     ceil((ceil(2R)+1)/2)^2 comparisons, (r+1)^2 for r texels where earlier
     versions took (2r)^2 comparisons (4, 9, 16, 49 for r = 1, 2, 3, 6 where
     they took 4, 16, 36, 144) for the same weights. The receiver plane
     compares each texel with its own plane depth: (ceil(2R)+1)^2
     comparisons, (2r+1)^2 for r texels, as before. Area lights (skgl_soft_*)
     use their own receiver-plane comparison inside their filters.

   FILTERABLE MAPS
     .filter = SKGL_FILTER_EVSM gives a directional light exponential
     variance shadow maps (EVSM: Lauritzen and McCool 2008, "Layered Variance
     Shadow Maps", Sec. 4). After its depth passes, each map's depth x =
     2z - 1 is warped by exp(40 x) and -exp(-40 x), the two warps and their
     squares are box-filtered over 2 .evsm_blur + 1 texels a side (two
     full-screen passes a map: a row, then a column) into an RGBA32F array,
     and a receiver is lit by the smaller of the two warps' Chebyshev upper
     bounds, read with one bilinear tap. Up to a 5-texel box (blur 2, the
     default) the moments have the map's own grid; a wider box is
     evaluated on a coarser grid, 5 points across it (a 1024^2 map at blur
     16: 156^2 moments), and the bilinear tap fills in between. Choose it
     for wide soft edges at a fixed cost: the draws are the same at every
     blur radius, and so is the work: the passes read at most about 10
     texels a map texel, once a frame, at any width, against PCF's
     (r + 1)^2 comparisons every screen pixel (tests/gl/test_gl_evsm.c:
     skgl_shadow_render of a 1024^2 map on llvmpipe 86 / 134 / 80 / 68 /
     56 ms at blur 1 / 2 / 4 / 8 / 16, where the box on the map's own grid
     took 87 / 122 / 258 / 298 / 506 ms). The map needs no comparison bias
     (no acne, slope-scaled offset only).
     Its price: light bleeding where casters overlap at different depths
     (a receiver under a low caster, inside a blur width of a high caster's
     edge, sees a little light; the positive warp keeps it small: on
     tests/gl/test_gl_evsm.c's two plates, no inner-shadow pixel above 0.05
     at a 5-texel blur, 1 of 1204 at 17 texels, where nearly plain variance
     maps leave 4.5% and 13.9%); .evsm_bleed cuts the bound's tail to take
     the rest away, moving edges toward the lit side. The blur widens the
     edges (the shadow-area error against the exact reference rises from
     PCF's 2.4% to 3.6% on ground-boxes, STANDARD 1024^2), and perspective
     maps (PSM) lose some of the warp's reach: their depth crowds near 1
     (7.4% against PCF's 2.3%). Very wide boxes (a quarter of the map)
     grey sloped open ground a little (the negative warp's bound), in
     faint bands of the coarse grid. Memory: 16 bytes a moments texel for
     every layer, plus side x map side for the row pass (depth, moments,
     row pass; at blur 2 or less a 2048^2 map: 16 + 64 + 64 MiB, 4
     cascades of 1024^2: 16 + 64 + 16 MiB; at blur 16, 311^2 moments for
     the 2048^2 map: 16 + 1.5 + 9.7 MiB). Needs float colour targets
     with linear filtering: OpenGL 3.3, or OpenGL ES / WebGL2 with
     GL_EXT_color_buffer_float and GL_OES_texture_float_linear (refused
     with SK_ERR_GL otherwise). Every technique that renders whole maps
     takes it: STANDARD, PSSM (layered or not), PSM, LiSPSM, LSPSM, FERKO,
     AUTO; RMSM is refused (desc.filter). Point and spot lights filter by
     PCF only. In a forward shader, "#define SK_SHADOW_EVSM 1" before the
     snippet compiles its EVSM part (a program with it takes units unit ..
     unit + 2, the moments on unit + 2; a program without it is refused for
     an EVSM light); the deferred mask of an EVSM light has it (a second
     mask program, made with the first EVSM light: PCF lights' mask stays
     as it was). With .cache the
     moments are blurred again every frame, from the cached depth.

   REFERENCES
     Ferko 2013, "Resolution Estimation for Shadow Mapping".
     Shen, Guennebaud, Yang and Feng 2011, "Predicted Virtual Soft Shadow
       Maps with High Quality Filtering" (PVSM).
     Stamminger and Drettakis 2002, "Perspective Shadow Maps"; Wimmer,
       Scherzer and Purgathofer 2004, "Light Space Perspective Shadow Maps";
       Zhang, Sun, Xu and Lun 2006, "Parallel-Split Shadow Maps"; Lefohn,
       Sengupta and Owens 2007, "Resolution-Matched Shadow Maps" (RMSM); as
       taught in Romanick's VGP353 course notes.
     Tang, Luo, Ni, Duan and Gao 2017, "Light Space Partitioned Shadow Maps".
     King and Newhall 2004, "Efficient Omnidirectional Shadow Maps" (VSDCT).
     Dou, Yan, Kerzner, Dai and Wyman 2014, "Adaptive Depth Bias for Shadow
       Maps", JCGT 3(4).
     Isidoro 2006, "Shadow Mapping: GPU-based Tips and Techniques", GDC.
     Castano 2013, "Shadow Mapping Summary - Part 1" (The Witness blog).
     Donnelly and Lauritzen 2006, "Variance Shadow Maps", I3D; Lauritzen
       2007, "Summed-Area Variance Shadow Maps", GPU Gems 3 ch. 8 (light-
       bleeding reduction); Lauritzen and McCool 2008, "Layered Variance
       Shadow Maps", Graphics Interface (the exponential warp, EVSM).

   GLSL SNIPPETS
     skgl_glsl_snippet() and skgl_point_glsl_snippet() are GLSL 330 core to
     paste after your #version line (the same text ships as the files
     shaders_embedded/shadow_sample.glsl and point_sample.glsl, for shader
     pipelines that include files); skgl_shadow_bind and skgl_point_bind
     set all of their uniforms, so a program holds one light of each kind.
     Their names, all prefixed, are reserved in your shader:
       directional: float sk_shadow(vec3 world_pos, vec3 world_normal,
         float view_depth) (view_depth: the distance along the camera's
         view direction, positive in front), and the uniforms
         sk_shadow_map (sampler2DArrayShadow, on `unit`), sk_light_vp[8],
         sk_splits[10], sk_layers, sk_blend_band, sk_bias_mode,
         sk_normal_bias, sk_plane_bias, sk_pcf_radius, sk_filter_world,
         sk_light_dir, sk_select_by_map, sk_select_extent, sk_map_extent,
         sk_rmsm, sk_page_table (sampler2D, on `unit` + 1), sk_rmsm_pages0,
         sk_rmsm_levels, sk_rmsm_min_level, sk_rmsm_page; with
         SK_SHADOW_EVSM defined, also sk_moments (sampler2DArray, on
         `unit` + 2), sk_filter, sk_evsm and the functions sk_chebyshev,
         sk_evsm_visibility; the global
         float sk_receiver_slack (0; yours to set: the world-space
         uncertainty of your positions); with "#define SK_SHADOW_CONTACT
         1" before the snippet (contact shadows in the forward snippet,
         skgl_shadow_contact_depth) also sk_contact_depth (sampler2D, on
         `unit` + 3), sk_contact, sk_contact_camera[3],
         sk_contact_depth_map and the functions sk_shadow_map_visibility,
         sk_contact_combine and sk_contact_*;
       point: float sk_point_shadow(vec3 world_pos, vec3 world_normal),
         and sk_point_cube (samplerCubeShadow) or, with SK_POINT_VSDCT,
         sk_point_atlas (sampler2DShadow) and sk_point_indirection
         (samplerCube, on `unit` + 1), sk_point_faces[6], sk_point_pos,
         sk_point_range, sk_point_depth, sk_point_texel,
         sk_point_normal_bias, sk_point_bias_mode, sk_point_plane_bias,
         sk_point_pcf; the global float sk_point_receiver_slack.
     Several lights in one program: each light gets its own copy of its
     snippet with its names under a prefix of yours,
     skgl_glsl_snippet_prefixed("sun0_", buf, size) (sk_shadow ->
     sun0_shadow, sk_light_vp -> sun0_light_vp, SK_ -> SUN0_) and
     skgl_point_glsl_snippet_prefixed("lamp0_", ...) (lamp0_point_shadow;
     a VSDCT lamp needs "#define LAMP0_POINT_VSDCT 1"); paste them all
     after #version, and bind each light under its prefix and on units of
     its own: skgl_shadow_bind_named(gl, sun0, prog, 0, "sun0_", NULL),
     skgl_point_bind_named(gl, lamp0, prog, 2, "lamp0_"). Each light takes
     two units (unit and unit + 1), so a fragment shader's 16 units hold 8
     lights. The bind caches locations per program and prefix.

   CAMERA CONVENTIONS
     skgl_camera.proj may be any of the projections engines use for the
     camera whose depth buffer shadowkit reads: OpenGL's (near at NDC z
     -1), reverse-Z (near at the larger depth: a GREATER depth test, depth
     cleared to 0), with a finite or an infinite far plane, perspective or
     orthographic. Reverse-Z and the infinite far plane are read from proj
     itself. The clip depth is the context's: skgl_desc.clip_zero_to_one = 1
     says your cameras draw under glClipControl(GL_LOWER_LEFT,
     GL_ZERO_TO_ONE) (proj maps to clip z in [0, w]; the window depth is
     NDC z). Every call reads the depth buffer in the camera's convention
     (positions rebuilt with your proj), fits the maps to the same camera
     in OpenGL's convention (an infinite far plane ends at the farthest
     corner of the scene's bounds, or at max_distance), and draws its own
     depth passes under OpenGL's clip depth: with clip_zero_to_one the
     render calls switch to GL_NEGATIVE_ONE_TO_ONE for their passes and
     give GL_ZERO_TO_ONE back at the end (two glClipControl calls; the
     origin is taken as GL_LOWER_LEFT). shadowkit's own maps keep OpenGL's
     depth: their precision is set by their crops, not by a far plane.

   GL STATE
     Two modes, skgl_desc.caller_owns_state:
     0 (the default): every call leaves the GL state as it found it. It
       reads only what it touches, once, the first time (glGet*, glIsEnabled),
       sets only what differs, and puts back only what it changed (a
       standard map's render and mask: 74 GL calls a frame, 29 of them
       reads; skgl_shadow_bind 10).
     1: nothing is read and nothing put back: each call sets what it needs
       (40 GL calls a frame for the same render and mask; skgl_shadow_bind
       6) and leaves it, but for framebuffer 0 (draw and read) and no
       pixel pack or unpack buffer, so that your next calls cannot land in
       shadowkit's objects. Set the state your own passes need after
       shadowkit's calls. What a call may leave:
         render (directional, point): depth test on, GL_LESS, depth writes
           on, culling off, polygon offset on with the light's bias (off
           without), polygon mode GL_FILL, scissor test off (FERKO's
           smaller maps, VSDCT: on, with its rectangle), its viewport,
           shadowkit's depth program, the vertex array your callback left;
         mask, analyze: blending and culling off, colour mask all on,
           polygon mode GL_FILL, scissor off (a point light's .scissor: on,
           with the light's rectangle), its viewport, its program, its
           empty vertex array, GL_PROGRAM_POINT_SIZE on (RMSM's analyze),
           GL_TEXTURE_CUBE_MAP_SEAMLESS on for a cube light's mask and off
           for VSDCT's, the pixel pack skips 0 (analyze; RMSM's also the
           pack alignment 1 and row length 0); textures on units 0-3: unit 0 the map (directional:
           with shadowkit's comparison sampler; point: sampler 0, the map
           compares by itself), 1 the depth texture, 2 the normals (both
           with shadowkit's nearest-texel sampler), 3 RMSM's page table or
           VSDCT's indirection (sampler 0); the analysis uses unit 1 only
           (left active); unit 0 active after a mask;
         skgl_soft_render (area lights): the mask's state above (its
           resolve or PCSS mask program), depth test on with GL_LESS and
           writes, polygon offset on with the light's bias (off without),
           depth clamp off; PVSM also blending's equation GL_FUNC_ADD and
           function GL_ONE, GL_ONE (blending itself off),
           GL_PROGRAM_POINT_SIZE on, the scissor box of its tile passes;
           textures on units 0-3: PCSS 0 its map (nearest-texel sampler),
           1 and 2 the G-buffer, 3 its map (comparison sampler); PVSM 0 its
           low-res pyramid (sampler 0) and its screen targets (2D array),
           1 its accumulation (sampler 0), 2 the normals, 3 its plain low-
           res map;
         create calls: texture unit 0 bindings, unpack alignment 1, row
           length and skips 0, the last program linked (skgl_create);
         skgl_*_bind: the map and its sampler on `unit`, RMSM's page table
           or VSDCT's indirection on `unit` + 1, which stays active.
       The one read this mode makes: a point light's resolution selection
       without .screen_w/.screen_h reads the viewport. Program locations
       are trusted from the cache (skgl_forget_program).
     In both modes a pass sets glPolygonMode(GL_FILL) (a host drawing in
     wireframe gets filled maps and masks) and puts the caller's program
     back only if glIsProgram says it still exists (a program deleted while
     current lives only as long as it stays current: Dear ImGui's issue
     #6220). Framebuffers are checked complete when they are made (and a
     cube light's again when its mip level changes); the mask texture is
     attached to shadowkit's mask framebuffer at every mask call, checked
     the first time its name comes by, and stays attached until the next
     mask call (skgl_forget_texture lets go of it at once). Sizes of your
     textures are asked once per name (skgl_forget_texture after giving one
     new storage; desc.debug asks every time and refuses a size that
     changed under the same name). Uniform locations are looked up at link time for
     shadowkit's programs and on the first skgl_*_bind of yours (a cache of
     16 programs); constants (sampler units, filter, bias) are sent when a
     program holds another light's, the rest when it changes or, for the
     matrices, split depths, light direction and position, every call.
     Area lights (skgl_soft_*) go through the same tracker, each target
     with a framebuffer of its own made once (the screen-sized ones again
     when the mask's size changes): PCSS 68 calls a frame (36 in caller-
     owns mode), PVSM 167 with one tile (120). With desc.debug set, glGetError is checked after every pass
     and a GL error is reported as SK_ERR_GL (ERRORS AND MISUSE). skgl_gl_object_count() tells
     how many GL objects the context holds (0 after every shadow and the
     context are destroyed).

   ERRORS AND MISUSE
     Every call that can fail returns an sk_result; every one that takes
     the context clears skgl_error_log on entry and, on failure, leaves one
     message there naming the call, the argument or field, its value and
     the rule ("skgl_shadow_create: desc.cascades = -2: in
     1..SKGL_MAX_CASCADES (8; 0: the default)"). The same
     messages go to skgl_desc.logger (func + user, sokol's sg_desc.logger;
     zero: none) as they are written, which is how skgl_create, which has
     no context to return when it fails, says why: a desc field, the
     entry point desc.getproc did not return (by name), a GL version below
     3.3 core / ES 3.0, or the driver's compile log of shadowkit's own
     shaders. skgl_create(NULL, ..) has nobody to tell.
     GL errors: an error the application left pending (a glGetString(
     GL_EXTENSIONS) on a core context, as older GLEW does) is not
     shadowkit's. The create calls always, and with desc.debug every call
     that checks, clear it first and name it as a warning ("GL error
     pending before skgl_shadow_render: GL_INVALID_ENUM", level
     SKGL_LOG_WARNING, the log holding it while the call succeeds; after
     skgl_create, only the logger); it never fails the call. Without desc.debug the per-frame calls do not read
     glGetError, and an error left pending stays the application's. With
     desc.debug, a GL error raised during a call is SK_ERR_GL naming the
     error and where it came from: shadowkit's set-up of a caster pass,
     the draw callback of that pass (its kind and layer or face), or the
     call's mask pass or own state changes.
     Refused (SK_ERR_INVALID_ARG, named in the log): zero, inverted,
     non-finite or huge (beyond 1e18) scene bounds (SCENE ACCESS); a render,
     analysis, mask or create from inside a draw callback (the outer pass's
     program and model location would be lost); a mask or bind of a light
     never rendered; a texture name that is not a texture, or a depth or
     normal texture without storage (where GL can be asked its size);
     skgl_remember_texture sizes above GL_MAX_TEXTURE_SIZE; and, with
     desc.debug, a bind to a program that is not current, not a program, or
     lacks the snippet under the prefix given (its map sampler is not an
     active uniform: the snippet is missing, was pasted under another
     prefix, or its shadow function is never called; without the check the
     map lands on a unit another sampler type of the program may read, and
     the draw raises GL_INVALID_OPERATION).
     Not detected, as in stb and sokol: a light, caster or atlas used after
     it was destroyed, destroyed twice, or passed to another context than
     the one that made it; a context used after skgl_destroy or on another
     thread; GL objects of the context deleted by the application; a draw
     callback that breaks SCENE ACCESS without desc.debug (shadowkit then
     binds its own program again before sending it anything, but the rest
     of what the callback changed stays changed). These are undefined
     behaviour.

   DOES NOT DO
     - Spot lights as a light of their own: a spot is a point light with a
       cone (SPOT LIGHTS), one perspective map; .cache keeps it as a point
       light keeps its faces (CACHED MAPS).
     - World-sized filtering (.filter_world) and the filterable map
       (SKGL_FILTER_EVSM) for point lights and spots: both are directional
       only; point lights and spots filter with .pcf_radius in texels.
     - Threads: no call locks anything. A context and everything made from
       it are used from one thread at a time, with the GL context they were
       made in current there. Two skgl contexts, each over its own GL
       context, share nothing and may be used at once.
     - Context sharing: one skgl_context per GL context. Its GL objects are
       used only in the GL context current at their create; share lists do
       not make a light usable from another skgl_context (and GL never
       shares framebuffers or vertex arrays).
     - Detecting the misuse listed under "Not detected" above (use after
       destroy, double destroy, another context's objects, another thread,
       GL objects deleted behind its back, SCENE ACCESS broken without
       desc.debug).

   DEBUGGING (for tests and debugging views; not needed to draw shadows)
     The declarations end with these, grouped under DEBUGGING:
     skgl_gl_object_count (GL objects the context holds: 0 after everything
     is destroyed), skgl_shadow_texture (the depth array), skgl_shadow_pages
     and skgl_shadow_analysis_texture (RMSM's pages and last analysis),
     skgl_soft_tiles and skgl_soft_pyramid (PVSM's tiles and SMTG pyramid).
     And in the descs: skgl_desc.disable_caps (run a phone's or browser's
     path on a desktop: OPENGL ES 3.0 AND WEBGL2), .verify_cache of
     skgl_shadow_desc and skgl_point_desc (every cached map checked against
     an uncached one, a CPU-GPU stall: CACHED MAPS; its result in
     stats.cache_verify_texels), and skgl_desc.debug (ERRORS AND MISUSE).

   READ-BACKS
     What the CPU needs from the GPU (FERKO's estimate, 32 bytes; RMSM's
     page requests, a byte per page of every level: 32 KB for 16384 /
     128, four bytes with the finer bands of .rmsm_band_pages) is read
     into the next of three pixel pack buffers, followed by a
     fence. Later calls poll the fences with a zero timeout (never waiting;
     the poll flushes, or a fence might never reach the GPU) and use the
     newest buffer that has landed: a frame late on a GPU that keeps up,
     more on one that does not, and the last result stays in use until a
     newer one lands. When all three are still in flight no new read-back
     is issued. Read back in the same frame, with the stall that costs
     (the CPU waits for the GPU to finish every command before it):
     .sync_readback = 1, every frame; the first analysis of a light (no
     earlier result exists), once. A FERKO light never analysed renders
     the focused map at full resolution; an RMSM light, the coarsest page.
     PVSM (skgl_soft_render) reads its Shadow Map Tile Grid the same way,
     one read of grid x (grid + 1) RGBA32F texels (66560 bytes at the
     default 64: the grid's predicted texel sizes and, in the row above,
     the pixel counts of stats.lit_fraction; the pyramid is built on the
     CPU) and tiles from the newest prediction landed, carried into this
     frame's light frustum (skgl_soft_tile_rects): the same light position
     and frame, exactly (a rectangle's sides keep their tangents); a light
     that moved or turned, each tile's pyramid between the prediction's
     near and far planes bounded in the new frustum (a little larger). It
     reads at once, with that stall, on .sync_readback = 1, on a light's
     first render, and when a tile of the landed prediction reaches behind
     the light's plane as it is now; stats.prediction_age and
     readback_sync say which. Under motion the region a frame newly shows
     has no tile for that frame (lit); measured on the test scene, camera
     at up to 30 cm a frame and the light at 5 cm, within a few percent of
     this frame's prediction (tests/gl/test_gl_soft_rings.c).

   LARGE WORLDS
     Directional lights work relative to an origin near the camera (its
     position rounded to SKGL_ORIGIN_CELL, 256 m by default; zero near the
     world origin): crops are fitted there, the depth pass moves your models
     there in double (skgl_set_model) and the mask reconstructs positions
     there, so a scene 1e5 from the world origin shadows as one at it, and
     stable crops keep a texel grid fixed in world space. Everything you
     pass and get stays in world space. A forward shader that works
     camera-relative uses skgl_shadow_bind_origin. Point and area lights
     work in world space.

   TIMING
     With desc.timing set, each timed pass (render, mask, analyze) of a
     directional or point light takes the next of three GL_TIME_ELAPSED
     queries. Before it, the query three passes old (about to be reused)
     and the one two passes old are read if GL_QUERY_RESULT_AVAILABLE says
     they are done; if the older is not, the pass goes untimed rather than
     wait. skgl_shadow_stats() reports the latest result read (two frames
     old; -1 before the first), shadow texels rendered and draw passes.
     desc.timing = SKGL_TIMING_SYNC reads each pass's query right after it
     (GL_QUERY_RESULT: the CPU waits for the GPU, once per timed pass), so
     the stats hold this frame's times: for benchmarks, never for shipping.
     An area light's frame has a varying number of timed passes (PVSM: two
     per tile), so each of its frames takes a set of queries (one per
     pass, the set grown as needed), read whole when the set comes round
     three frames later, or two, if every result is there; a set still
     busy leaves that frame untimed. stats.step_ms holds each step's sum.

   OPENGL ES 3.0 AND WEBGL2
     The same header runs on OpenGL ES 3.0 and later and on WebGL2
     (Emscripten). skgl_desc.api's zero reads GL_VERSION ("OpenGL ES ..."
     is ES); skgl_create probes what the context offers into skgl_caps
     (skgl_get_caps), and every shader gets its dialect's first lines:
     "#version 300 es" with highp precision for floats, ints and every
     sampler type ("320 es" where geometry shaders exist), "#version 330
     core" on the desktop. The snippets declare their samplers highp, so
     they paste into an ES shader that sets only `precision highp float`.
     A technique that needs what the context lacks fails at create with
     SK_ERR_GL and a log naming the feature and its extension. Per
     technique:
       STANDARD, PSSM, PSM, LiSPSM, LSPSM, cube, PCSS   ES 3.0 core.
       FERKO        float colour targets (GL_EXT_color_buffer_float).
       RMSM         float targets and blending (+ GL_EXT_float_blend).
       VSDCT        without RG16 (GL_EXT_texture_norm16) the indirection
                    cube is replaced by the same face mapping in the
                    shader (SK_POINT_VSDCT_ANALYTIC; define it too in a
                    forward shader on such a context).
       PVSM         float targets and blending. Without a geometry
                    shader its conservative low-resolution pass becomes
                    a plain one 4 times finer (depth-tested: no float
                    blending needed there), reduced per texel to the
                    minimum over its 4x4 block grown by one fine texel:
                    casters thinner than a fine texel can slip between
                    its centres (test_gl_es measures the fence's 2 cm
                    slats: the masks 0.0079 apart, mean |difference| over
                    the penumbra). Where a texture cannot be sampled while
                    one of its levels is drawn (WebGL2: ANGLE calls it a
                    feedback loop; skgl_caps.mip_render_level), its MIN
                    pyramid reads copies of its levels. Without depth
                    clamp (GL_EXT_depth_clamp) casters before the light's
                    near plane are clipped; the plane is fitted to the
                    scene's bounds, so only geometry outside them is.
       layered      geometry shaders (ES 3.2): desc.layered fails on ES 3.0.
       clip_zero_to_one  GL_EXT_clip_control.
     What differs in use:
       - ES 3.0 and WebGL2 cannot be asked a texture's size: give the size
         of every texture you pass (camera depth, normals, masks) once with
         skgl_remember_texture (again after new storage).
       - Read-backs use glGetBufferSubData on WebGL2, glMapBufferRange on
         ES 3.0. A browser signals a fence only after the script yields:
         run frames from requestAnimationFrame (the read-backs land a frame
         or two later), or set .sync_readback.
       - Timer queries come from GL_EXT_disjoint_timer_query (ES) or
         GL_EXT_disjoint_timer_query_webgl2 (enable it first); without
         them the stats' times read -1. A read that finds
         GL_GPU_DISJOINT_EXT set keeps the previous times (one glGet per
         read, on ES only).
       - WebGL2 refuses a draw when any sampler of its program, used or
         not, names a unit holding the texture being drawn to: the mask
         passes bind no texture on the units they leave unused there.
       - Emscripten 3.1's emscripten_webgl_get_proc_address leaves out
         glGetBufferSubData; wrap it (web/shadowkit_web.c shows how).
       - Chromium's software WebGL (SwiftShader) offsets depth far less per
         polygon offset unit than Mesa: point lights with the receiver-plane
         bias show false shadow there (2% of the pixels in the test scene);
         SKGL_BIAS_NORMAL_OFFSET, or depth_bias 64, brings them back.
       - GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_PROGRAM_POINT_SIZE, the polygon
         mode and depth clamp without the extension are never touched
         (ES samples cube maps seamlessly and takes gl_PointSize always).
     skgl_desc.disable_caps turns capabilities off on a richer context, to
     run a phone's or a browser's path on a desktop (the tests do).

   LICENSE: see the end of the file.
*/
#ifndef SHADOWKIT_GL_H
#define SHADOWKIT_GL_H

/* the release of this header; shadowkit.h must be the same one */
#define SHADOWKIT_GL_VERSION_MAJOR 0
#define SHADOWKIT_GL_VERSION_MINOR 1
#define SHADOWKIT_GL_VERSION_PATCH 0

#include "shadowkit.h"

#if !defined(SHADOWKIT_VERSION_MAJOR) || SHADOWKIT_VERSION_MAJOR != SHADOWKIT_GL_VERSION_MAJOR || \
    SHADOWKIT_VERSION_MINOR != SHADOWKIT_GL_VERSION_MINOR || SHADOWKIT_VERSION_PATCH != SHADOWKIT_GL_VERSION_PATCH
#error "shadowkit_gl.h and the shadowkit.h it includes are of different releases: use the pair shipped together"
#endif

#ifndef SKGLDEF
#define SKGLDEF SKDEF
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define SKGL_MAX_CASCADES 8
#define SKGL_CACHE_REGIONS 16         /* invalidated boxes a cached light keeps between renders */
#define SKGL_PREFIX_MAX 24            /* the longest prefix of a prefixed GLSL snippet */
#define SKGL_SOFT_STEPS 8            /* area light steps timed in skgl_soft_frame_stats.step_ms */

typedef void *(*skgl_getproc_fn)(const char *name);

typedef enum skgl_pass_kind {
    SKGL_PASS_DIRECTIONAL = 0,    /* a layer of a directional light's map (index = cascade) */
    SKGL_PASS_CUBE_FACE = 1,      /* a face of a point light's cube (index = face, +X,-X,+Y,-Y,+Z,-Z) */
    SKGL_PASS_AREA = 2,           /* an area light's map (skgl_soft): index 0 PCSS's map or PVSM's
                                     low-resolution map, 1 + i PVSM tile i */
    SKGL_PASS_CAMERA = 3,         /* skgl_soft's own G-buffer (depth_tex = 0): the camera's view */
    SKGL_PASS_SPOT = 4            /* a spot light's map (SPOT LIGHTS; index 0, info.point the light) */
} skgl_pass_kind;
struct skgl_point;

typedef struct skgl_draw_info {
    skgl_pass_kind kind;
    int index;                    /* cascade / layer */
    sk_mat4 view_proj;            /* world -> clip of this pass */
    sk_frustum frustum;           /* of view_proj, for culling */
    /* SKGL_PASS_CUBE_FACE: the light, and the point light itself for
       skgl_point_caster_visible() (NULL for other passes) */
    sk_vec3 light_pos;
    float light_range;
    struct skgl_point *point;
    /* shadowkit's depth program, current when the callback starts: a
       callback that binds a program of its own binds this one again before
       it returns (SCENE ACCESS) */
    unsigned program;
    /* Layered single-pass rendering (desc.layered, LAYERED PASSES): 0 when
       the callback draws one layer (index); n > 0 when what it draws goes
       to n layers at once (index -1; view_proj and frustum those of
       layer_view_proj[0]): entry i is cascade, cube face or RMSM page
       layer_index[i], for culling against any of them. */
    int layers;
    int layer_index[SKGL_MAX_CASCADES];
    sk_mat4 layer_view_proj[SKGL_MAX_CASCADES];
    sk_frustum layer_frustum[SKGL_MAX_CASCADES];
    /* 1: this call is the skgl_set_dynamic callback (the casters that move, CACHED
       MAPS); 0: scene.draw's */
    int dynamic;
    /* w > 0: the pass draws only into this texel rectangle of its
       viewport (x, y, w, h from the viewport's corner, where view_proj's
       NDC [-1, 1] spans it: a cached map's newly exposed strip, an
       invalidated region, the part of an RMSM page the dynamic casters
       touch; the viewport is the whole layer or face, RMSM's the page's
       slot of rmsm_page_size + 2 texels a side), so a callback may skip
       casters whose shadow misses it; all 0: the whole viewport */
    int rect[4];
} skgl_draw_info;
typedef void (*skgl_draw_fn)(void *user, const skgl_draw_info *info);

#define SKGL_TIMING_SYNC 2            /* skgl_desc.timing: every pass timed and read at once */

/* Which OpenGL the context speaks (OPENGL ES 3.0 AND WEBGL2) */
typedef enum skgl_api {
    SKGL_API_AUTO = 0,            /* read from GL_VERSION: "OpenGL ES ..." (WebGL2 through
                                     Emscripten says "OpenGL ES 3.0 (WebGL 2.0 ...)") is
                                     SKGL_API_GLES3, anything else SKGL_API_GL33 */
    SKGL_API_GL33 = 1,            /* desktop OpenGL 3.3 core or later: "#version 330 core" */
    SKGL_API_GLES3 = 2            /* OpenGL ES 3.0 or later, WebGL2: "#version 300 es" (320 es
                                     where geometry shaders are used) with highp precision */
} skgl_api;

/* skgl_desc.disable_caps: capabilities treated as absent even when the
   context has them (to run a phone's or a browser's path on a desktop, or
   to keep a program off a slow feature). Each names a field of skgl_caps. */
#define SKGL_CAP_GEOMETRY_SHADER   0x0001u
#define SKGL_CAP_GPU_SHADER5       0x0002u
#define SKGL_CAP_FLOAT_RENDER      0x0004u
#define SKGL_CAP_FLOAT_BLEND       0x0008u
#define SKGL_CAP_NORM16            0x0010u
#define SKGL_CAP_DEPTH_CLAMP       0x0020u
#define SKGL_CAP_TIMER_QUERY       0x0040u
#define SKGL_CAP_TEXTURE_SIZE      0x0080u
#define SKGL_CAP_BUFFER_READ       0x0100u
#define SKGL_CAP_CLIP_CONTROL      0x0200u
#define SKGL_CAP_MIP_RENDER_LEVEL  0x0400u

/* What the context offers, probed once by skgl_create (skgl_get_caps).
   1: present and used; 0: absent (or disabled), and the techniques that
   need it take the fallback OPENGL ES 3.0 AND WEBGL2 lists, or fail at
   create naming it. */
typedef struct skgl_caps {
    skgl_api api;                 /* the API in use (never SKGL_API_AUTO) */
    int major, minor;             /* GL_MAJOR_VERSION, GL_MINOR_VERSION */
    int webgl;                    /* 1: WebGL2 (GL_VERSION names it) */
    int geometry_shader;          /* GL 3.2, ES 3.2: PVSM's conservative pass, layered passes */
    int gpu_shader5;              /* GL 4.0 / GL_ARB_gpu_shader5, ES 3.2: geometry shader
                                     invocations (layered passes; else a loop) */
    int float_render;             /* 32- and 16-bit float colour targets: GL 3.0,
                                     GL_EXT_color_buffer_float on ES (FERKO, RMSM, PVSM) */
    int float_blend;              /* blending into 32-bit float targets: GL 3.0,
                                     GL_EXT_float_blend on ES (RMSM's requests, PVSM's MIN
                                     pyramid) */
    int norm16;                   /* RG16 unorm textures: GL 3.0, GL_EXT_texture_norm16 on ES
                                     (VSDCT's indirection; else RG32F) */
    int depth_clamp;              /* GL 3.2, GL_EXT_depth_clamp on ES (PVSM's low-resolution
                                     pass; else clamped in its shader) */
    int timer_query;              /* GL 3.3, GL_EXT_disjoint_timer_query(_webgl2) on ES:
                                     the stats' GPU times (else -1) */
    int texture_size;             /* glGetTexLevelParameteriv: GL, ES 3.1 (else the size of a
                                     texture you pass comes from skgl_remember_texture) */
    int buffer_read;              /* glGetBufferSubData: GL, WebGL2 (else glMapBufferRange) */
    int clip_control;             /* glClipControl: GL 4.5 / GL_ARB_clip_control,
                                     GL_EXT_clip_control on ES (skgl_desc.clip_zero_to_one) */
    int mip_render_level;         /* rendering into one mip level while sampling another of
                                     the same texture: GL, ES; refused by ANGLE (WebGL2), so
                                     PVSM's pyramid reads copies of its levels there */
    int max_texture_size;         /* GL_MAX_TEXTURE_SIZE */
} skgl_caps;

/* skgl_desc.logger (sokol's sg_desc.logger is the model): every message
   the context writes into skgl_error_log is also handed to func as it is
   written, so a skgl_create that fails (and leaves no context to ask) can
   still say why: the field, the missing entry point by name, the GL
   version, the driver's compile log. level says whether the call fails
   (SKGL_LOG_ERROR) or goes on (SKGL_LOG_WARNING: a GL error the
   application left pending, cleared). message is valid during the call
   only. A zero logger (func NULL) logs nothing. */
typedef enum skgl_log_level {
    SKGL_LOG_ERROR = 0,
    SKGL_LOG_WARNING = 1
} skgl_log_level;
typedef void (*skgl_log_fn)(void *user, skgl_log_level level, const char *message);
typedef struct skgl_logger {
    skgl_log_fn func;             /* NULL: no logger */
    void *user;                   /* handed back to func */
} skgl_logger;

typedef struct skgl_desc {
    skgl_getproc_fn getproc;      /* required */
    int debug;                    /* glGetError after each pass -> SK_ERR_GL naming the error and
                                     the pass (an application's pending error is cleared and
                                     named as a warning first); checks the draw callback's
                                     program, the cached program locations and the programs
                                     the binds are given (ERRORS AND MISUSE) */
    int timing;                   /* GL timer queries into the stats, read two or three frames
                                     late; SKGL_TIMING_SYNC: each pass's own time, read at
                                     once (a stall per timed pass: for benchmarks) */
    int clip_zero_to_one;         /* 1: your cameras draw under glClipControl(.., GL_ZERO_TO_ONE)
                                     (GL 4.5 / ARB_clip_control): their projections map to clip
                                     z in [0, w], window depth is NDC z (CAMERA CONVENTIONS)
                                     [0: OpenGL's -1..1] */
    int caller_owns_state;        /* 0: every call leaves the GL state as it found it (reads
                                     what it touches, puts back what it changed); 1: no
                                     state is read or put back, each call sets what it
                                     needs and leaves what GL STATE lists [0] */
    skgl_api api;                 /* [SKGL_API_AUTO: read from GL_VERSION] */
    unsigned disable_caps;        /* DEBUGGING: SKGL_CAP_* bits treated as absent [0: use all there are] */
    skgl_logger logger;           /* every message of skgl_error_log, as it is written, skgl_create's
                                     own included [zero: none] */
} skgl_desc;

typedef enum skgl_technique {
    SKGL_STANDARD = 0,            /* one focused (or stable) orthographic map */
    SKGL_PSSM = 1,                /* parallel-split cascades */
    SKGL_PSM = 2,                 /* perspective shadow map (one map) */
    SKGL_LISPSM = 3,              /* light-space perspective map; cascades > 1: one per PSSM slice */
    SKGL_LSPSM = 4,               /* light space partitioned maps (Tang et al. 2017) */
    SKGL_FERKO = 5,               /* crop and resolution estimated from the G-buffer (Ferko 2013) */
    SKGL_RMSM = 6,                /* virtual map rendered page by page at the requested levels (Romanick's VGP353 notes) */
    SKGL_AUTO = 7                 /* the library chooses: one focused map or up to .cascades cascades, per
                                     frame, from the view's depth range and the scene (CHOOSING FOR YOU) */
} skgl_technique;

/* How a receiver is kept out of its own shadow (BIAS AND FILTERING) */
typedef enum skgl_bias {
    SKGL_BIAS_RECEIVER_PLANE = 0, /* each filtered texel compared with the receiver's tangent
                                     plane at the texel's centre: no acne on flat receivers,
                                     no shadow moved (the default) */
    SKGL_BIAS_NORMAL_OFFSET = 1,  /* the receiver pushed along its normal by .normal_bias
                                     texels: moves every shadow edge toward the light */
    SKGL_BIAS_NONE = 2            /* the plain comparison, only the polygon offset: to
                                     see acne and measure the other two */
} skgl_bias;

/* How a directional light's map is filtered (BIAS AND FILTERING, FILTERABLE MAPS) */
typedef enum skgl_filter {
    SKGL_FILTER_PCF = 0,          /* percentage-closer filtering of the depth map (.pcf_radius) */
    SKGL_FILTER_EVSM = 1          /* exponential variance shadow maps: a blurred RGBA32F moments
                                     map beside the depth map (Lauritzen and McCool 2008) */
} skgl_filter;

/* Zero-initialised fields take the default in brackets. */
typedef struct skgl_shadow_desc {
    skgl_technique technique;     /* [SKGL_STANDARD] */
    int resolution;               /* texels per side of each map, 1 or more (2 or more with
                                     .stable) [2048] */
    int cascades;                 /* PSSM, 1..SKGL_MAX_CASCADES [4] */
    float lambda;                 /* PSSM split scheme weight in (0, 1] (AUTO: before its first
                                     analysis; after it, 1) [0.75; with .fit_to_depth, left 0:
                                     0.75 before the first analysis, 1 after it] */
    int uniform_splits;           /* 1: lambda 0, the uniform split scheme [0] */
    float splits[SKGL_MAX_CASCADES - 1];  /* PSSM, LiSPSM per cascade: hand-set view depths where
                                     cascade i ends and i + 1 begins, increasing, one per
                                     boundary (cascades - 1), the rest 0; all 0: lambda's
                                     scheme [0]. Each frame they are kept inside the shadow
                                     range (the camera's near plane to the end of the
                                     shadows): a boundary past it makes its cascades thin. */
    float blend_band;             /* PSSM: fraction of a cascade blended into the next [0: off] */
    int stable;                   /* 1: texel-snapped crops whose size steps on a fixed ladder
                                     (STABLE CROPS), 0 or 1 [0] */
    int stable_sphere;            /* 1 with .stable: each crop bounds its cascade's sphere, the
                                     same size at every camera position and orientation, at
                                     the price of covering more than the view needs [0] */
    float slope_bias;             /* polygon offset factor, 0 or more [2.0] */
    float depth_bias;             /* polygon offset units, 0 or more [1.0] */
    int disable_polygon_offset;   /* 1: no polygon offset in the depth passes [0] */
    float normal_bias;            /* receiver normal offset in texels, 0 or more [1.5 with
                                     SKGL_BIAS_NORMAL_OFFSET, none with the receiver plane] */
    skgl_bias bias;               /* [SKGL_BIAS_RECEIVER_PLANE] */
    float plane_bias;             /* receiver plane: comparison tolerance in texels of the
                                     plane's own depth slope, 0..64 [0.5] */
    int disable_plane_bias;       /* 1: no tolerance beyond the plane itself [0] */
    int pcf_radius;               /* the filter's half-width in texels, 1..8, when .filter_world
                                     is 0: (r+1)^2 hardware 2x2 compares [1] */
    float filter_world;           /* the filter's half-width in world units (metres if your
                                     scene is in metres), across the light's direction: the
                                     same penumbra in every cascade, at every resolution and
                                     in every technique (but RMSM: one 2x2 compare), up to
                                     8 texels of a layer (BIAS AND FILTERING); 0 or more
                                     [0: .pcf_radius texels] */
    int disable_pcf_kernel;       /* 1: one hardware 2x2 compare, no kernel [0] */
    int cache;                    /* 1: keep scene.draw's (static) casters' depth from frame
                                     to frame and redraw only what changed (CACHED MAPS):
                                     STANDARD, PSSM, PSM, LiSPSM, LSPSM; RMSM keeps its
                                     pages [0] */
    int cache_budget_kb;          /* .cache: the most GPU memory the cache may take, in KiB;
                                     the nearest layers are cached while they fit, the rest
                                     drawn every frame (RMSM: the static copy of the pool
                                     under dynamic casters, or none) [0: no limit] */
    int verify_cache;             /* DEBUGGING. .cache, desktop GL: also render every cached layer
                                     (RMSM: page) uncached, read both back (a CPU-GPU stall:
                                     for debugging) and fail the render when they differ
                                     beyond float rounding (CACHED MAPS) [0] */
    float max_distance;           /* shadows end at this view depth [camera far] */
    float fade_band;              /* where the scene goes on past the end of the shadows
                                     (max_distance, the camera's far plane), they fade to
                                     lit over this fraction of the last layer's depth range
                                     before it, instead of ending at a hard line; in (0, 1]
                                     [0.1; not RMSM, whose pages cover the scene] */
    int disable_fade;             /* 1: shadows end at a hard line [0] */
    sk_lspsm_params lspsm;        /* LSPSM: Eq. (1) parameters; zero fields take
                                     the paper's zeta 0.25, sigma 0.5, h_max 4,
                                     nw_max 2 (h_max * nw_max <= SKGL_MAX_CASCADES) */
    int sync_readback;            /* FERKO, RMSM: 0 (the default) the estimate or the page
                                     requests of an earlier frame (the last whose read-back
                                     has landed: a frame late on a GPU that keeps up),
                                     through a ring of fenced pixel buffers, no stall; fast
                                     motion can clip FERKO's crop or leave RMSM a frame on
                                     coarser pages. 1: this frame's, read back at once (a
                                     CPU-GPU stall every frame). The first analysis reads
                                     at once either way. */
    int rmsm_page_size;           /* RMSM: page side in texels, a power of two in [16, 1024] [128] */
    int rmsm_pool_pages;          /* RMSM: the physical pool holds this^2 pages, 2..64 [24];
                                     .resolution is the virtual map's side, a power
                                     of two [16384 for RMSM], at most 1024 pages.
                                     The pool is one depth texture of (this x
                                     (.rmsm_page_size + 2))^2 32-bit texels: 24, 3120^2,
                                     39 MB; 48, 6240^2, 156 MB. Measured (bench, 1280x720,
                                     16384^2 virtual, shadow-area error, mean of 3 views):
                                     sponza-ivy 6.75% at 24, 4.02% at 48 (standard 2048^2
                                     12.89%); terrace 7.21%, 3.75% (10.17%); at 48 the
                                     frame draws 3.2x the pages (1715 and 1407 against 535
                                     and 445) in 1.3-1.4x the time. 24 stays the default
                                     for its memory and passes; 48 where the view needs
                                     the pages */
    int rmsm_band_pages;          /* RMSM: finer pages than the pixel-matched level, in at most
                                     this many slots (the whole pool where even the
                                     pixel-matched pages overflow it and the finest level
                                     rises): none coarser than the finest world size
                                     they afford and, where they afford it too, a texel of half
                                     a pixel (a caster thinner than a pixel, a pole's shadow at
                                     500 m, needs texels under the pixel; stats.rmsm_band,
                                     rmsm_band_finer). [0: the pool, half of
                                     it with .cache, the rest kept for earlier frames' pages];
                                     -1: the pixel-matched level alone (Lefohn, Sengupta and
                                     Owens 2007); else 1..rmsm_pool_pages^2 */
    float psm_slide;              /* PSM: the virtual camera slides back by this
                                     times sqrt(near*far) of the receivers, its
                                     near plane with it: more uniform texels,
                                     0..1000 [0.5] */
    int disable_psm_slide;        /* 1: no slide (the plain PSM) [0] */
    int layered;                  /* 1: a light of several layers (PSSM, LSPSM, LiSPSM with
                                     cascades) draws them all in one pass through a
                                     geometry shader: one callback instead of one per
                                     layer (LAYERED PASSES); RMSM: a callback per
                                     SKGL_MAX_CASCADES pages; 0: a pass per layer [0] */
    int fit_to_depth;             /* 1: STANDARD, PSSM, LiSPSM: the shadow range, and the
                                     splits over it, is the view depths the depth buffer
                                     holds (sample distribution shadow maps, Lauritzen,
                                     Salvi and Lefohn 2011): call skgl_shadow_analyze each
                                     frame (an earlier frame's range through the read-back
                                     ring, no stall; .sync_readback: this frame's), split
                                     logarithmically unless .lambda is set. Not with
                                     .stable or .cache. SKGL_AUTO always does this [0] */
    float auto_texel_px;          /* SKGL_AUTO: the texel-to-pixel ratio wanted: the fewest maps
                                     whose worst texel spans at most this many pixels of the
                                     depth buffer analysed; when none does, the fewest within
                                     25% of the smallest ratio. More than 0 [1.0] */
    int disable_auto_warp;        /* SKGL_AUTO: 1: focused maps only, never a LiSPSM warp [0] */
    float contact_length;         /* contact shadows in skgl_shadow_mask: a march this long (world
                                     units: a few centimetres to decimetres) from each receiver
                                     toward the light through the camera's depth buffer, its
                                     result min()'d with the map's; it restores the shadow the
                                     map's bias lifts off a caster's foot; with normal_tex
                                     (without, it does little). In the forward snippet with
                                     SK_SHADOW_CONTACT and skgl_shadow_contact_depth. Not for
                                     point lights. 0 or more [0: off] */
    int contact_steps;            /* the march's depth-buffer samples, 1..64 [8] */
    float contact_thickness;      /* a sample is blocked by a surface in front of it by less
                                     than this (world units): thin casters throw no endless
                                     shadow; more than 0 [contact_length] */
    skgl_filter filter;           /* SKGL_FILTER_EVSM: the filterable map (FILTERABLE MAPS): STANDARD,
                                     PSSM, PSM, LiSPSM, LSPSM, FERKO, AUTO; not RMSM. Needs float
                                     targets with linear filtering (OpenGL ES: GL_EXT_color_buffer_float
                                     and GL_OES_texture_float_linear) [SKGL_FILTER_PCF] */
    int evsm_blur;                /* EVSM: the blur's radius in texels, a (2r+1)^2 box, 1..64; the same
                                     draws and about the same work at every radius [2] */
    int disable_evsm_blur;        /* 1: EVSM without the blur (bilinear taps of the moments only) [0] */
    float evsm_bleed;             /* EVSM: light-bleeding reduction, the part of the Chebyshev bound
                                     cut off (Lauritzen 2007): less light where casters overlap,
                                     edges moved toward the lit side; in [0, 1) [0: none] */
} skgl_shadow_desc;

typedef struct skgl_camera {
    sk_mat4 view, proj;           /* proj: a perspective (sk_mat4_perspective, glm::perspective) or
                                     orthographic projection; near and far are read back from
                                     it, and so is reverse-Z (the near plane at depth 1) and an
                                     infinite far plane (CAMERA CONVENTIONS) */
} skgl_camera;

typedef struct skgl_scene {
    skgl_draw_fn draw;            /* required: the casters (the static ones, for a cache) */
    void *user;
    sk_aabb bounds;               /* all casters and receivers: clips the maps and ends the shadow
                                     range (SCENE ACCESS); a box of some size, finite */
} skgl_scene;

/* The casters that move or change (CACHED MAPS), given to
   skgl_set_dynamic: drawn in every caster pass after scene.draw, and over
   a cached map's static depth every frame (info->dynamic 1). */
typedef struct skgl_dynamic {
    skgl_draw_fn draw;            /* required */
    void *user;
    sk_aabb bounds;               /* where they are this frame: a cached map copies and draws
                                     them only in the texels it covers (and restores last
                                     frame's) [all 0: not given, the whole map] */
} skgl_dynamic;

/* What a directional light's last frame did (skgl_shadow_stats). */
typedef struct skgl_shadow_frame_stats {
    float shadow_ms;              /* GPU time of the depth passes (the latest measured: two frames
                                     old, TIMING); -1 without timing or before the first */
    float mask_ms;                /* GPU time of a skgl_shadow_mask, likewise */
    float analysis_ms;            /* FERKO, RMSM: GPU time of a skgl_shadow_analyze, likewise */
    double texels;                /* shadow texels rendered (sum of viewport areas) */
    int passes;                   /* draw callbacks made */
    int maps;                     /* layers rendered */
    int resolution;               /* per layer */
    int map_width, map_height;    /* texels rendered per layer (FERKO: the estimate, clamped) */
    float splits[SKGL_MAX_CASCADES + 1];  /* view depths of the layers */
    /* warping (PSM, LiSPSM), per layer */
    float warp_n[SKGL_MAX_CASCADES];      /* LiSPSM: n of the warp (n_opt); +INF: uniform map */
    int warped[SKGL_MAX_CASCADES];        /* 1: the layer's map is perspective-warped */
    int depth_reversed;                   /* PSM: light behind the viewer (depth order flipped back) */
    float psm_slide;                      /* PSM: how far the virtual camera slid back */
    int lspsm_fallback;                   /* LSPSM: no trapezoid axis (view along the light): one focused map */
    sk_res_estimate estimate;             /* FERKO: the estimate the last render used, in the clip
                                             space of estimate_light (see skgl_shadow_analyze) */
    sk_mat4 estimate_light;               /* FERKO: the uncropped light frustum of that estimate */
    int pages_requested;                  /* RMSM: distinct pages the view asked for (finest levels) */
    int pages_rendered;                   /* RMSM: pages drawn this frame (uncached: every page of the
                                             frame, the coarsest always among them) */
    int rmsm_min_level;                   /* RMSM: finest level rendered (> 0 when the pool was short
                                             even for the pixel-matched pages; a band may sit above it) */
    int rmsm_band;                        /* RMSM: the request band of this frame's pages, the finest the
                                             pool held: 0 the pixel-matched level; b > 0 at most level
                                             levels - 1 - b (desc.rmsm_band_pages) and, with
                                             rmsm_band_finer, one level finer than the pixel */
    int rmsm_band_finer;                  /* RMSM: 1 when band b > 0's pages are also a level finer than
                                             the pixel; 0: the cap alone (the pool held no more) */
    int pages_reused;                     /* RMSM, .cache: pages of this frame kept from an earlier one */
    int pages_evicted;                    /* RMSM, .cache: resident pages whose slot a new page took */
    int pages_resident;                   /* RMSM: pages the pool holds (uncached: this frame's) */
    int layered;                          /* 1: the layers went in one pass (desc.layered honoured;
                                             RMSM: its pages SKGL_MAX_CASCADES at a pass);
                                             2: so, through one geometry shader invocation per layer
                                             (GL_ARB_gpu_shader5) */
    /* the cache (desc.cache, CACHED MAPS): cached layers this frame drawn
       whole, scrolled (only the exposed strips drawn), reused as they
       were; regions redrawn for skgl_shadow_invalidate; texels copied
       between the cache and the map; the GPU memory the cache holds; the
       layers it holds (the nearest, within cache_budget_kb). RMSM:
       cache_full 1 when every page was emptied (a new light, scene
       bounds, skgl_shadow_invalidate(NULL)), cache_reused 1 when none
       was, cache_regions the pages invalidated boxes emptied */
    int cache_full, cache_scrolled, cache_reused, cache_regions;
    double cache_copied;
    double cache_bytes;
    int cache_layers;
    int cache_verify_texels;              /* .verify_cache: texels of the last render that differ
                                             from the uncached map, side by side (beyond a scroll's
                                             float rounding, CACHED MAPS; -1: not verified) */
    /* .fit_to_depth and SKGL_AUTO (CHOOSING FOR YOU) */
    float depth_lo, depth_hi;             /* the view depths the analysis found, widened by the
                                             margin the fit used (0 0: no analysis yet) */
    skgl_technique auto_technique;        /* AUTO: SKGL_STANDARD (one map), SKGL_PSSM (cascades)
                                             or SKGL_LISPSM (warped maps) */
    float auto_texel_px[SKGL_MAX_CASCADES];  /* AUTO: with k + 1 maps, the predicted texel size in
                                             pixels at the near end of the worst map (0: not tried) */
    float auto_texel_px_warped[SKGL_MAX_CASCADES];  /* AUTO: the same maps warped (LiSPSM), the
                                             worst over each map's depths (0: not tried, no
                                             slice warped, an orthographic camera, or
                                             .disable_auto_warp) */
    char auto_reason[192];                /* AUTO: the choice in words */
    float auto_lambda;                    /* AUTO: the split weight of the cascades (0 with one map;
                                             1, the log scheme, over an analysed range) */
    int auto_crops;                       /* AUTO: crops fitted this frame: each count's once
                                             (1 + 2 + .. + .cascades, every count scored by its
                                             crops; the chosen count's are kept, not refitted) */
    int auto_analysed;                    /* AUTO: 1 when the last skgl_shadow_analyze ran the
                                             analysis, 0 when it kept the last one (the view had
                                             not moved: CHOOSING FOR YOU) */
    double auto_bytes;                    /* AUTO: bytes of its depth texture now (layers x side^2
                                             x 4; CHOOSING FOR YOU, Memory) */
} skgl_shadow_frame_stats;


typedef struct skgl_context skgl_context;
typedef struct skgl_shadow skgl_shadow;

SKGLDEF sk_result skgl_create(const skgl_desc *desc, skgl_context **out);
SKGLDEF void skgl_destroy(skgl_context *ctx);
/* inside a draw callback: model matrix of the next objects (column-major) */
SKGLDEF void skgl_set_model(skgl_context *ctx, const float model[16]);

/* Caster programs (CASTER PROGRAMS): the user's vertex code, and optionally
   an alpha test, linked into every caster pass that needs them. */
#define SKGL_CASTER_UNIFORMS 16       /* names whose locations skgl_use_caster returns */
typedef struct skgl_caster_desc {
    const char *vertex;           /* required: GLSL 3.30 declarations (attributes, uniforms,
                                     buffers) and  vec4 skgl_caster_position(void),  the
                                     vertex in the space skgl_set_model's matrix takes to
                                     the world (the world itself under the identity) */
    const char *fragment;         /* optional: declarations and  void skgl_caster_fragment(void),
                                     which may discard (an alpha test); samplers on units 4
                                     and up (shadowkit's passes leave those alone) */
    const char *varyings;         /* optional: what the vertex hook hands the fragment hook,
                                     one  [qualifiers] type name;  each ("vec2 uv; flat int
                                     id;"), qualifiers flat, smooth, noperspective, centroid,
                                     a precision; comments and #if/#ifdef/#else/#endif/
                                     #define lines kept; at most 16, no arrays or lists:
                                     written and read by name (CASTER PROGRAMS) */
    const char *uniforms[SKGL_CASTER_UNIFORMS];  /* the uniforms the callback sets, by name,
                                     in the order of the locations skgl_use_caster returns */
    const char *label;            /* names the caster in messages ["caster"] */
} skgl_caster_desc;
typedef struct skgl_caster skgl_caster;
/* Compiles and links the hooks into the depth passes' program at once (a
   compile error is returned here, SK_ERR_GL, the log quoting the driver's
   message with the hook's own line numbers; shadowkit's own lines are
   numbered from 10001); the area lights' low-resolution and G-buffer
   programs are linked the first time a pass of theirs uses the caster. The
   strings are copied. */
SKGLDEF sk_result skgl_caster_create(skgl_context *ctx, const skgl_caster_desc *desc, skgl_caster **out);
/* frees its programs (skgl_destroy frees those left) */
SKGLDEF void skgl_caster_destroy(skgl_context *ctx, skgl_caster *caster);
/* Inside a draw callback: the objects drawn next are this caster's (NULL:
   shadowkit's own program again). Binds the caster's program for this pass,
   its view-projection and the pass's own uniforms set, the model the
   identity; returns the locations of desc.uniforms, in order (-1: not
   found or not used), for the callback to set with the program bound. NULL
   when the program could not be linked: the render call then returns
   SK_ERR_GL with the driver's message in the log. After the callback
   shadowkit's own program is current again. */
SKGLDEF const int *skgl_use_caster(skgl_context *ctx, skgl_caster *caster);
/* skgl_*_bind looks a program's uniform locations up once and remembers
   them (and which light's constants it holds) by program name. The default
   mode notices a program linked again or made anew under a freed name (two
   reads a bind); with caller_owns_state it reads nothing: call this after
   linking the program again, or when deleting it */
SKGLDEF void skgl_forget_program(skgl_context *ctx, unsigned program);
/* the masks and the analysis remember a texture's size (when the camera
   gives none) and that it is renderable, by name: call this after giving
   the texture new storage, or before deleting it (a mask texture stays
   attached to shadowkit's framebuffer until the next mask call; this lets
   go of it at once) */
SKGLDEF void skgl_forget_texture(skgl_context *ctx, unsigned texture);
/* tells shadowkit the size of a texture you pass it (a mask target, a
   camera depth buffer): needed where GL cannot be asked (skgl_caps
   .texture_size 0: OpenGL ES 3.0, WebGL2), harmless elsewhere. Call it
   again after giving the texture new storage. SK_ERR_INVALID_ARG for texture
   0, a name that is not a texture, or a size outside 1..GL_MAX_TEXTURE_SIZE. */
SKGLDEF sk_result skgl_remember_texture(skgl_context *ctx, unsigned texture, int width, int height);
/* what skgl_create probed (zeros for NULL) */
SKGLDEF skgl_caps skgl_get_caps(const skgl_context *ctx);

SKGLDEF sk_result skgl_shadow_create(skgl_context *ctx, const skgl_shadow_desc *desc, skgl_shadow **out);
SKGLDEF void skgl_shadow_destroy(skgl_context *ctx, skgl_shadow *s);
/* the desc with its defaults filled in */
SKGLDEF skgl_shadow_desc skgl_shadow_get_desc(const skgl_shadow *s);
/* Renders the light's map(s) for this camera. light_dir: travel direction. */
SKGLDEF sk_result skgl_shadow_render(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                     const skgl_scene *scene, sk_vec3 light_dir);
/* Deferred shadow mask: depth_tex is the camera's depth texture (window
   depth; any depth or single-channel float format), normal_tex an optional
   texture of world-space normals in .xyz (0: none, no normal offset),
   mask_tex an R16F (or any renderable single-channel) texture of the same
   size that receives visibility. */
SKGLDEF sk_result skgl_shadow_mask(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex);
/* CACHED MAPS: the dynamic casters of every render call that follows (all
   lights), until the next call; NULL: none. Copied: set it again when the
   bounds move. */
SKGLDEF sk_result skgl_set_dynamic(skgl_context *ctx, const skgl_dynamic *dyn);
/* CACHED MAPS (desc.cache): what scene.draw draws inside `box` (world
   space) changed, so the cached texels its shadow may cover are redrawn at
   the next render: give the box a static caster left and the one it came
   to, the box of a caster that appeared or went. box NULL: everything
   (the next render draws every layer whole). Up to SKGL_CACHE_REGIONS
   boxes between two renders; more are merged into their union. A light
   without a cache has nothing to redraw: SK_OK. */
SKGLDEF sk_result skgl_shadow_invalidate(skgl_context *ctx, skgl_shadow *s, const sk_aabb *box);
/* SKGL_RMSM: the same call finds the pages of the virtual map the view
   needs (per pixel level of detail from the screen derivatives of its
   virtual-map texel coordinates, requests reduced on the GPU, read back:
   by default through the ring, the render then draws the pages of the
   latest requests landed, READ-BACKS); the render draws them into the page
   pool. Without a call, only the coarsest page (the whole map at pool-page
   resolution) is rendered.
   SKGL_FERKO: estimates the crop and the resolution of a later
   skgl_shadow_render from the camera's depth texture (window depth, the
   G-buffer of the frame; Ferko 2013): the next render's with
   .sync_readback and on the first call, else the render after it lands
   (READ-BACKS). The light frustum before the crop is an orthographic map
   around scene->bounds; the estimate (stats.estimate, set by the render
   that uses it) is in its clip space. Call it before skgl_shadow_render
   with the same camera, scene and light. Nothing visible in the light: a
   1x1 map. Without a call, the render falls back to the focused map at
   full resolution. The depth texture's size is asked of GL once per name
   (skgl_forget_texture). */
SKGLDEF sk_result skgl_shadow_analyze(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                      const skgl_scene *scene, sk_vec3 light_dir, unsigned depth_tex);
/* GLSL (330 core) declaring the uniforms and
   float sk_shadow(vec3 world_pos, vec3 world_normal, float view_depth);
   Paste it into a fragment shader after the #version line. */
SKGLDEF const char *skgl_glsl_snippet(void);
/* The same snippet for one of several directional lights in one program
   (GLSL SNIPPETS, several lights): every name that starts with sk_ starts
   with prefix instead (sk_shadow -> sun0_shadow for "sun0_"), every SK_
   with prefix in capitals. Like snprintf: writes at most cap bytes into
   out (NUL-terminated; out may be NULL with cap 0) and returns the length
   of the whole text, or -1 when prefix is not a GLSL identifier of 1 to
   SKGL_PREFIX_MAX characters (a letter first, not gl_, no double
   underscore). Bind the light with skgl_shadow_bind_named(.., prefix, ..). */
SKGLDEF int skgl_glsl_snippet_prefixed(const char *prefix, char *out, int cap);
/* For a forward shader containing the snippet: program must be current;
   binds the map (and a comparison sampler) to texture unit `unit` and sets
   the snippet's uniforms. The binding is left in place for the draw.
   SK_ERR_INVALID_ARG for a light never rendered and, with desc.debug, for
   a program that is not current or lacks the snippet (ERRORS AND MISUSE).
   Unit `unit` + 1 is the RMSM page table's (bound there for SKGL_RMSM):
   keep it free of samplers of another type in that program. A program
   with SK_SHADOW_EVSM also takes unit + 2 (the EVSM moments, bound there
   for a light with SKGL_FILTER_EVSM; unit at most 29); an EVSM light bound
   to a program without it is SK_ERR_INVALID_ARG (FILTERABLE MAPS). */
SKGLDEF sk_result skgl_shadow_bind(skgl_context *ctx, const skgl_shadow *s, unsigned program, int unit);
/* Contact shadows in a forward shader (desc.contact_length > 0): the
   camera's depth buffer the snippet's march reads, depth_tex (a depth
   pre-pass of `cam`, in cam's depth convention; never the depth
   attachment the forward pass draws into: reading it while drawing is a
   feedback loop), 0: none. The shader declares "#define SK_SHADOW_CONTACT
   1" before the snippet (its uniforms: GLSL SNIPPETS); skgl_shadow_bind
   then binds depth_tex to unit + 3 (a nearest, non-comparing sampler
   there: keep that unit free) and sets the march's uniforms, and
   sk_shadow() min()s the map's visibility with the march's (the mask's
   march, the buffer's normals taken from its depth). Without the define,
   without a depth_tex or with contact_length 0 the bind sets nothing more
   (no call). Call it when the camera or the buffer changes (each frame
   for a moving camera), after skgl_shadow_render or before. */
SKGLDEF sk_result skgl_shadow_contact_depth(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                            unsigned depth_tex);
/* skgl_shadow_bind for a shader whose world positions are relative to
   `origin` (camera-relative rendering: sk_shadow() then takes
   world_pos - origin); NULL: world space, as skgl_shadow_bind */
SKGLDEF sk_result skgl_shadow_bind_origin(skgl_context *ctx, const skgl_shadow *s, unsigned program, int unit,
                                          const double origin[3]);
/* Several lights in one program (GLSL SNIPPETS, several lights): the bind
   of a light whose snippet came from skgl_glsl_snippet_prefixed(prefix);
   prefix NULL or "": the plain snippet's sk_ names. origin as in
   skgl_shadow_bind_origin (NULL: world space). */
SKGLDEF sk_result skgl_shadow_bind_named(skgl_context *ctx, const skgl_shadow *s, unsigned program, int unit,
                                         const char *prefix, const double origin[3]);
/* After drawing with a bound light: plain sampling again on `unit` and
   `unit` + 1 (the sampler objects skgl_shadow_bind / skgl_point_bind left
   there, a comparison sampler among them, unbound; the textures stay), so
   a later texture on those units samples by its own parameters. */
SKGLDEF sk_result skgl_unbind(skgl_context *ctx, int unit);
/* the message of the last failure of the last call that took the context
   ("" after a call that succeeded; a pending application GL error's
   warning when one was cleared: ERRORS AND MISUSE) */
SKGLDEF const char *skgl_error_log(const skgl_context *ctx);
/* light view-projection of one layer (world -> light clip) */
SKGLDEF sk_mat4 skgl_shadow_matrix(const skgl_shadow *s, int layer);
/* LSPSM: the mask samples the first layer whose light clip holds the point
   within |x|, |y| <= this times w (the partition's rect, less its margin);
   1 for the other techniques and before the first render */
SKGLDEF float skgl_shadow_select_extent(const skgl_shadow *s);
SKGLDEF const skgl_shadow_frame_stats *skgl_shadow_stats(const skgl_shadow *s);

/* ---- point lights: cube shadow maps and VSDCT (King & Newhall 2004) -----
   skgl_point *lamp;   once: skgl_point_create(gl, &pdesc, &lamp)
   every frame:
     skgl_point_render(gl, lamp, &cam, &scene, light_pos);
       calls scene.draw once per cube face that is rendered (info->kind =
       SKGL_PASS_CUBE_FACE, info->index = face); with .cull_casters the
       callback asks skgl_point_caster_visible(info, caster_aabb) per object
       and draws only those that pass (it may also draw everything).
     skgl_point_mask(gl, lamp, &cam, depth_tex, normal_tex, mask_tex);
       deferred mask, as skgl_shadow_mask; with .scissor only the light's
       rectangle (sk_light_scissor of the range box) is written: clear the
       mask to 1 first, or draw the light's lighting with the same scissor.
     or forward: "#define SK_POINT_VSDCT 1\n" (VSDCT only) before
       skgl_point_glsl_snippet() in a fragment shader, skgl_point_bind(), and
       float v = sk_point_shadow(world_pos, world_normal);
   King & Newhall's four optimizations are switches (all off: the naive cube, six
   faces, every caster, full resolution, the whole screen), so each can be
   measured alone. */
typedef enum skgl_point_technique {
    SKGL_POINT_CUBE = 0,          /* native GL_TEXTURE_CUBE_MAP depth, samplerCubeShadow */
    SKGL_POINT_VSDCT = 1          /* six faces in one 2D depth atlas + RG16 indirection cube map */
} skgl_point_technique;

typedef struct skgl_point_atlas skgl_point_atlas;

typedef struct skgl_point_desc {
    skgl_point_technique technique; /* [SKGL_POINT_CUBE] */
    int resolution;               /* texels per face side, the most rendered [512]; a power
                                     of two for SKGL_POINT_CUBE with .select_resolution */
    float near_plane;             /* of every face [0.05] */
    float range;                  /* far plane = light range [10] */
    float slope_bias;             /* polygon offset factor, 0 or more [2.0] */
    float depth_bias;             /* polygon offset units, 0 or more [1.0] */
    int disable_polygon_offset;   /* 1: no polygon offset in the face passes [0] */
    float normal_bias;            /* receiver normal offset in face texels, 0 or more [1.5
                                     with SKGL_BIAS_NORMAL_OFFSET, none with the receiver plane] */
    skgl_bias bias;               /* [SKGL_BIAS_RECEIVER_PLANE] */
    float plane_bias;             /* receiver plane: extra tolerance in texels of the plane's
                                     depth slope, beyond the one texel a 2x2 comparison
                                     reaches, 0..64 [0.5] */
    int disable_plane_bias;       /* 1: no extra tolerance [0] */
    int pcf_radius;               /* (2r)^2 hardware 2x2 compares, 1..8 [1] */
    int disable_pcf_kernel;       /* 1: one hardware 2x2 compare, no kernel [0] */
    int cull_faces;               /* 1: skip faces whose frustum misses the view (sk_cube_visible_faces) */
    int cull_casters;             /* 1: skgl_point_caster_visible culls by the caster's shadow
                                     frustum against the view and by the face frustum */
    int scissor;                  /* 1: the mask pass only inside sk_light_scissor's rectangle */
    int select_resolution;        /* 1: face side from sk_cube_resolution (N M^2 >= c S) */
    float resolution_c;           /* c of the selection [2, King & Newhall's] */
    int screen_w, screen_h;       /* S of the selection: pixels of the light's rectangle on a
                                     screen this size [0: the viewport bound at render time] */
    int vsdct_grey_levels;        /* G of Eq. (5.4.7) for the indirection size (D = 8), 2..65536
                                     [256] */
    skgl_point_atlas *atlas;      /* SKGL_POINT_VSDCT only: the six faces live in this shared
                                     atlas, placed by skgl_point_atlas_pack [NULL: an atlas of
                                     the light's own, 3 x 2 faces of .resolution] */
    int layered;                  /* SKGL_POINT_CUBE: 1 draws the faces it renders in one pass
                                     through a geometry shader, one callback a frame
                                     (LAYERED PASSES); VSDCT keeps a pass per face [0] */
    int cache;                    /* 1: keep the faces' static depth (scene.draw's casters)
                                     while the light stays put; redraw only what
                                     skgl_point_invalidate names (CACHED MAPS); not with
                                     .layered or a shared .atlas [0] */
    int cache_budget_kb;          /* .cache: the most GPU memory the cache may take, KiB; a
                                     light whose cache is larger is drawn every frame [0: no
                                     limit] */
    int verify_cache;             /* DEBUGGING. .cache, desktop GL: also render every face the view needs
                                     uncached, read both back (a CPU-GPU stall: for
                                     debugging) and fail the render when they differ
                                     (CACHED MAPS) [0] */
    float spot_angle;             /* > 0: a spot light, the cone's half-angle in degrees, at
                                     most 85: one perspective map (SPOT LIGHTS; technique is
                                     then SKGL_POINT_VSDCT's storage), drawn by skgl_spot_render
                                     [0: omnidirectional] */
} skgl_point_desc;

/* What a point light's last frame did (skgl_point_stats). */
typedef struct skgl_point_frame_stats {
    float shadow_ms;              /* GPU time of the face passes (two frames old, TIMING); -1
                                     without timing or before the first */
    float mask_ms;                /* GPU time of a skgl_point_mask, likewise */
    double texels;                /* shadow texels rendered (sum of viewport areas) */
    int passes;                   /* draw callbacks made */
    int resolution;               /* face side rendered this frame */
    int faces_rendered, faces_culled;     /* cube faces drawn / skipped by face culling */
    int casters_drawn, casters_culled;    /* (face, caster) pairs skgl_point_caster_visible passed / culled */
    int scissor[4];                       /* the last mask's rectangle x, y, w, h (all 0: nothing drawn) */
    int atlas_wanted;                     /* shared atlas: face side selected before packing (greater
                                             than .resolution when skgl_point_atlas_pack halved it to fit) */
    int layered;                          /* as skgl_shadow_frame_stats.layered, for the faces */
    /* the cache (desc.cache): faces drawn this frame from the cache as they
       were (the others drawn whole), regions redrawn for
       skgl_point_invalidate, texels copied, the GPU memory it holds (0:
       no cache) */
    int faces_reused, cache_regions;
    double cache_copied, cache_bytes;
    int cache_verify_texels;              /* .verify_cache: texels of the last render that differ
                                             from the uncached faces, side by side (CACHED MAPS;
                                             -1: not verified) */
} skgl_point_frame_stats;

typedef struct skgl_point skgl_point;

SKGLDEF sk_result skgl_point_create(skgl_context *ctx, const skgl_point_desc *desc, skgl_point **out);
SKGLDEF void skgl_point_destroy(skgl_context *ctx, skgl_point *p);
/* the desc with its defaults filled in */
SKGLDEF skgl_point_desc skgl_point_get_desc(const skgl_point *p);
/* Renders the faces the view needs for a light at light_pos. */
SKGLDEF sk_result skgl_point_render(skgl_context *ctx, skgl_point *p, const skgl_camera *cam,
                                    const skgl_scene *scene, sk_vec3 light_pos);
/* inside a SKGL_PASS_CUBE_FACE callback: 0 when this caster box's shadow
   cannot be seen in this frame through this face (its shadow frustum,
   light to box to range, misses the view frustum, or the box misses the
   face), 1 otherwise; always 1 without .cull_casters or outside a point
   pass. Counted in the stats. */
SKGLDEF int skgl_point_caster_visible(const skgl_draw_info *info, sk_aabb caster);
/* CACHED MAPS (desc.cache): what scene.draw draws inside `box` changed;
   NULL: everything. As skgl_shadow_invalidate. */
SKGLDEF sk_result skgl_point_invalidate(skgl_context *ctx, skgl_point *p, const sk_aabb *box);
/* Deferred point-light mask, arguments as skgl_shadow_mask. */
SKGLDEF sk_result skgl_point_mask(skgl_context *ctx, skgl_point *p, const skgl_camera *cam,
                                  unsigned depth_tex, unsigned normal_tex, unsigned mask_tex);
/* GLSL (330 core) declaring the uniforms and
   float sk_point_shadow(vec3 world_pos, vec3 world_normal);
   SKGL_POINT_VSDCT needs "#define SK_POINT_VSDCT 1" before it. */
SKGLDEF const char *skgl_point_glsl_snippet(void);
/* skgl_glsl_snippet_prefixed for a point light: sk_point_shadow ->
   lamp0_point_shadow, SK_POINT_VSDCT -> LAMP0_POINT_VSDCT for "lamp0_";
   bind with skgl_point_bind_named */
SKGLDEF int skgl_point_glsl_snippet_prefixed(const char *prefix, char *out, int cap);
/* For a forward shader with the snippet, program current: binds the map to
   unit `unit` (VSDCT: the indirection cube map to unit + 1) and sets the
   uniforms. The bindings stay for the draw. Turn GL_TEXTURE_CUBE_MAP_SEAMLESS
   on for SKGL_POINT_CUBE (filtering across faces) and off for
   SKGL_POINT_VSDCT (the indirection must not blend faces). */
SKGLDEF sk_result skgl_point_bind(skgl_context *ctx, const skgl_point *p, unsigned program, int unit);
/* skgl_point_bind for a snippet from skgl_point_glsl_snippet_prefixed(prefix) */
SKGLDEF sk_result skgl_point_bind_named(skgl_context *ctx, const skgl_point *p, unsigned program, int unit,
                                        const char *prefix);
SKGLDEF const skgl_point_frame_stats *skgl_point_stats(const skgl_point *p);
/* the depth texture: GL_TEXTURE_CUBE_MAP (cube) or GL_TEXTURE_2D atlas (VSDCT;
   the shared atlas's texture with desc.atlas) */
SKGLDEF unsigned skgl_point_texture(const skgl_point *p);
/* VSDCT: the atlas layout of the last render (faces at the side rendered;
   in a shared atlas, the rectangles of the last skgl_point_atlas_pack) */
SKGLDEF sk_vsdct_layout skgl_point_layout(const skgl_point *p);

/* ---- spot lights: a skgl_point with desc.spot_angle > 0 (SPOT LIGHTS) -----
   skgl_point *spot;   once: skgl_point_create(gl, &pdesc, &spot), pdesc.spot_angle = 30
   every frame:
     skgl_spot_render(gl, spot, &cam, &scene, light_pos, direction);
       calls scene.draw once (info->kind = SKGL_PASS_SPOT); with
       .cull_casters the callback asks skgl_point_caster_visible(info, box),
       which culls by the cone (sk_spot_box_visible) and by the caster's
       shadow against the view.
     skgl_point_mask / skgl_point_bind as for a point light (the mask is 0
       outside the cone); forward: "#define SK_POINT_SPOT 1\n" before
       skgl_point_glsl_snippet(), or LAMP0_POINT_SPOT before a prefixed one. */
/* Renders the spot's map: one perspective projection from light_pos down
   `direction` (any length > 0), fitted to the cone clipped by
   scene->bounds (sk_spot_window), at .resolution, or the side
   sk_cube_resolution selects for one face (.select_resolution). */
SKGLDEF sk_result skgl_spot_render(skgl_context *ctx, skgl_point *p, const skgl_camera *cam, const skgl_scene *scene,
                                   sk_vec3 light_pos, sk_vec3 direction);

/* ---- several point lights in one atlas (King & Newhall 2004's VSDCT, shared) ---
   skgl_point_atlas *atlas;  once: skgl_point_atlas_create(gl, 4096, 2048, &atlas)
   each light: desc.technique = SKGL_POINT_VSDCT (or a spot, desc.spot_angle > 0),
     desc.atlas = atlas
   every frame:
     skgl_point_atlas_pack(gl, atlas, lights, n, &cam, light_positions);
     then per light skgl_point_render / skgl_point_mask / skgl_point_bind.
   The pack selects each light's face side as skgl_point_render would
   (.resolution, or sk_cube_resolution with .select_resolution), places the
   square faces (six a point light's, one a spot's) on shelves (largest
   first, left to right, a new shelf above when a row is full) and refills
   each light's indirection cube map for its rectangles. When they do not fit, the largest side is halved
   (the first light's on ties) until they do; the stats' atlas_wanted keeps
   the side selected. skgl_point_render of an atlas light then renders the
   side packed (it needs a pack first, SK_ERR_INVALID_ARG otherwise) and
   clears only its own faces; lookups are clamped to each face's rectangle,
   so a light never reads another's texels. Destroy the lights before the
   atlas. */
SKGLDEF sk_result skgl_point_atlas_create(skgl_context *ctx, int width, int height, skgl_point_atlas **out);
SKGLDEF void skgl_point_atlas_destroy(skgl_context *ctx, skgl_point_atlas *a);
/* light_pos[i] is lights[i]'s position this frame (the one given to its
   render). SK_ERR_CAPACITY when even faces of one texel do not fit; no
   light is placed anew then (each keeps its last placement, if any). */
SKGLDEF sk_result skgl_point_atlas_pack(skgl_context *ctx, skgl_point_atlas *a, skgl_point *const *lights, int n,
                                        const skgl_camera *cam, const sk_vec3 *light_pos);
/* the GL_TEXTURE_2D depth texture; its size */
SKGLDEF unsigned skgl_point_atlas_texture(const skgl_point_atlas *a);
SKGLDEF void skgl_point_atlas_size(const skgl_point_atlas *a, int *width, int *height);

/* ---- area lights: soft shadows (Shen et al. 2011) -----------------------
   A rectangular light at `position` facing `direction`; its maps are
   perspective projections from the rectangle's centre, aligned with the
   rectangle (skgl_area_light_axes gives the world half-axes, e.g. for a
   ray-traced reference). Both techniques take the camera's G-buffer (window
   depth + world normals, the size of the mask; depth_tex = 0: rendered
   through the draw callback) and write visibility into mask_tex in one call:

     skgl_soft *soft;      once: skgl_soft_create(gl, &softdesc, &soft)
     every frame: skgl_soft_render(gl, soft, &cam, &scene, &light,
                                   depth_tex, normal_tex, mask_tex);

   SKGL_SOFT_PCSS  percentage-closer soft shadows (Fernando 2005) on one map
                   of .resolution: blocker search, penumbra estimate, PCF.
   SKGL_SOFT_PVSM  predicted virtual soft shadow maps (Shen Li et al. 2011,
                   Sec. 5.2), eight steps, each timed in stats.step_ms:
                   0 the G-buffer (when rendered here), 1 the .lowres map
                   with conservative rasterisation, 2 the kernel-shape
                   buffer (blocker search, filter axes u_h, v_h, fully-lit
                   pixels flagged), 3 the prediction (Eqs. 4, 5) into the
                   .grid^2 Shadow Map Tile Grid by one point per pixel with
                   MIN blending, 4 the SMTG read back (one read of level 0,
                   its pyramid built on the CPU by sk_smtg_pyramid; by
                   default a frame late, .sync_readback) and the kd-tree of
                   tiles (sk_fvsm_tiles), 5 one map per tile at
                   its predicted resolution up to .resolution, 6 the smooth
                   texel-coverage filtering of every pixel whose kernel
                   meets the tile, merged as V*A / A, 7 the resolve.
                   A zero-size light gives hard shadows through the same
                   path (one texel per pixel footprint).
   Receivers behind the light's plane are outside its maps: lit. */
typedef enum skgl_soft_technique {
    SKGL_SOFT_PCSS = 0,
    SKGL_SOFT_PVSM = 1
} skgl_soft_technique;

typedef struct skgl_area_light {
    sk_vec3 position;             /* centre of the rectangle */
    sk_vec3 direction;            /* the way it faces (any length > 0) */
    sk_vec3 up;                   /* the rectangle's second axis, roughly (zero: any) */
    float half_width, half_height;/* along direction x up, and up; 0, 0: hard shadows */
} skgl_area_light;


/* Zero-initialised fields take the default in brackets. */
typedef struct skgl_soft_desc {
    skgl_soft_technique technique; /* [SKGL_SOFT_PCSS] */
    int resolution;               /* PCSS: the map's side [2048]; PVSM: the largest tile's [4096] */
    int lowres;                   /* PVSM: the conservative low-resolution map's side, a power of two
                                     in 16..8192 [1024] */
    int grid;                     /* PVSM: the SMTG's side, a power of two in 4..256 [64] */
    int max_tiles;                /* PVSM: at most this many tiles; more halve every
                                     predicted resolution until they fit, 1..4096 [64] */
    int disable_conservative;     /* PVSM: 1 the low-res map rasterised plainly (thin casters
                                     can vanish from the blocker search) [0] */
    int static_scene;             /* PVSM: 1 rho_static (only the camera moves) [0: rho_dynamic] */
    int blocker_cells;            /* blocker search samples per axis, 2..16 [8] */
    int pcf_taps;                 /* PCSS: PCF taps per axis at most, 1..16 [12] */
    float slope_bias;             /* polygon offset factor of the depth passes, 0 or more [1.5] */
    float depth_bias;             /* polygon offset units, 0 or more [1.0] */
    int disable_polygon_offset;   /* 1: no polygon offset in the depth passes [0] */
    float rel_bias;               /* comparison tolerance, fraction of the distance to the
                                     light, 0..0.5 [0.002] */
    int disable_antialias;        /* PVSM: 1 the kernel is the light's filter alone, as a
                                     point-sampled reference sees it; 0 the warped pixel
                                     footprint is convolved into every kernel (Sec. 4.2,
                                     anisotropic anti-aliasing) [0] */
    float resolution_scale;       /* PVSM: every predicted resolution times this, the quality
                                     against speed trade-off (Sec. 7), 0.125..8 [1] */
    int sync_readback;            /* PVSM: 0 (the default) the tiles come from the prediction of
                                     an earlier frame (the last whose read-back has landed, a
                                     frame late on a GPU that keeps up), through a ring of
                                     fenced pixel buffers, no stall; its tiles are carried
                                     into this frame's light frustum (READ-BACKS). 1: this
                                     frame's prediction, read back at once (a CPU-GPU stall
                                     every frame). The first render reads at once either way. */
} skgl_soft_desc;

/* What an area light's last frame did (skgl_soft_stats). */
typedef struct skgl_soft_frame_stats {
    float shadow_ms;              /* GPU time of the depth passes (PCSS: its map; PVSM: steps 1
                                     and 5), two or three frames old (TIMING); -1 without
                                     timing or before the first */
    float mask_ms;                /* GPU time of the rest but the G-buffer, likewise */
    float step_ms[SKGL_SOFT_STEPS];   /* GPU ms per step, likewise (PCSS: 0 the G-buffer, 1 the
                                     map, 7 the mask; PVSM: the eight steps); -1: not timed */
    double texels;                /* shadow texels rendered (the low-res map included) */
    int passes;                   /* draw callbacks made */
    int maps;                     /* maps rendered (PVSM: the tiles') */
    int resolution;               /* the largest side rendered */
    int tiles;                    /* PVSM: tile maps rendered */
    float lit_fraction;           /* PVSM: covered pixels the low-res map settled without filtering
                                     (fully lit, facing away, outside the light), counted in
                                     the prediction's read-back (as old as the prediction);
                                     -1 for PCSS */
    int prediction_age;           /* PVSM: frames since the prediction the tiles came from was
                                     made (0: this frame's, read back at once) */
    int readback_bytes;           /* PVSM: bytes this frame read back (at once, or into the ring) */
    int readback_sync;            /* PVSM: 1 when this frame's read-back waited for the GPU */
} skgl_soft_frame_stats;

typedef struct skgl_soft skgl_soft;

SKGLDEF sk_result skgl_soft_create(skgl_context *ctx, const skgl_soft_desc *desc, skgl_soft **out);
SKGLDEF void skgl_soft_destroy(skgl_context *ctx, skgl_soft *s);
SKGLDEF skgl_soft_desc skgl_soft_get_desc(const skgl_soft *s);
/* The light's maps and the mask in one call (PVSM renders and uses each
   tile's map in turn). SK_ERR_DEGENERATE: the whole scene is behind the
   light's plane (the mask is not written). */
SKGLDEF sk_result skgl_soft_render(skgl_context *ctx, skgl_soft *s, const skgl_camera *cam,
                                   const skgl_scene *scene, const skgl_area_light *light,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex);
/* stats: shadow_ms = the depth passes (PCSS: its map; PVSM: steps 1 and 5),
   mask_ms = the rest but the G-buffer; tiles, texels (low-res map included),
   lit_fraction, step_ms (PVSM) */
SKGLDEF const skgl_soft_frame_stats *skgl_soft_stats(const skgl_soft *s);
/* world-space half-axes of the light's rectangle, as its maps see it */
SKGLDEF void skgl_area_light_axes(const skgl_area_light *light, sk_vec3 *half_u, sk_vec3 *half_v);
/* the base frustum of the last render (world -> light clip); PVSM tiles
   are sk_crop_matrix crops of it (skgl_soft_tile_rects) */
SKGLDEF sk_mat4 skgl_soft_matrix(const skgl_soft *s);
/* PVSM: the rectangles of the last render's tiles (skgl_soft_tiles) as it drew them, in clip
   units of its base frustum (skgl_soft_matrix), carried there from the
   prediction's; writes at most cap, returns how many there are */
SKGLDEF int skgl_soft_tile_rects(const skgl_soft *s, sk_rect *out, int cap);

/* ---- DEBUGGING: for tests and debugging views (the manual's DEBUGGING) --- */
/* GL objects the context currently owns (its own and its lights'): 6 after
   skgl_create; the programs of FERKO's analysis (3: FERKO, AUTO,
   .fit_to_depth), RMSM's (2) and EVSM's are made with the first light that
   needs them and kept until skgl_destroy */
SKGLDEF int skgl_gl_object_count(const skgl_context *ctx);
/* the GL depth texture (GL_TEXTURE_2D_ARRAY), for debugging views (SKGL_AUTO:
   the same name, its size and layers those of the chosen count: CHOOSING FOR YOU) */
SKGLDEF unsigned skgl_shadow_texture(const skgl_shadow *s);
/* RMSM: the pages resident after the last skgl_shadow_analyze (or render),
   sorted by (level, py, px); writes at most cap, returns how many there are */
SKGLDEF int skgl_shadow_pages(const skgl_shadow *s, sk_page *out, int cap);
/* RMSM: the RGBA32F texture of the last analysis, (s, t, lod, 1) per pixel
   (0 where no sample); 0 before any */
SKGLDEF unsigned skgl_shadow_analysis_texture(const skgl_shadow *s);
/* PVSM: the tiles of the last render, cells of the SMTG of the prediction
   they came from (2/grid clip units per cell of that frame's base frustum,
   this frame's when stats.prediction_age is 0); writes at most cap,
   returns how many there are */
SKGLDEF int skgl_soft_tiles(const skgl_soft *s, sk_tile *out, int cap);
/* PVSM: the SMTG pyramid of the prediction the last render used, laid out
   as sk_smtg_pyramid's (+INFINITY: no sample); returns the float count
   (writes at most cap), 0 before any */
SKGLDEF int skgl_soft_pyramid(const skgl_soft *s, float *out, int cap);

#ifdef __cplusplus
}
#endif
#endif /* SHADOWKIT_GL_H */

/* =========================================================================
   IMPLEMENTATION
   ========================================================================= */
#ifdef SHADOWKIT_GL_IMPLEMENTATION
#ifndef SHADOWKIT_GL_IMPLEMENTATION_INCLUDED
#define SHADOWKIT_GL_IMPLEMENTATION_INCLUDED
#ifdef SK__STATIC_WITHOUT_IMPLEMENTATION
#error "SHADOWKIT_STATIC: define SHADOWKIT_IMPLEMENTATION with SHADOWKIT_GL_IMPLEMENTATION before this file's first #include of shadowkit.h"
#endif
/* the GL implementation uses shadowkit.h's internal helpers: both in one file */
#ifndef SHADOWKIT_IMPLEMENTATION_INCLUDED
#error "SHADOWKIT_GL_IMPLEMENTATION needs SHADOWKIT_IMPLEMENTATION defined in the same file (before the #include)"
#endif

#include <ctype.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(SKGL_MALLOC) != defined(SKGL_FREE)
#error "shadowkit_gl.h: define both SKGL_MALLOC and SKGL_FREE, or neither (CONFIGURATION)"
#endif
#ifndef SKGL_MALLOC
#define SKGL_MALLOC(n) malloc(n)
#define SKGL_FREE(p) free(p)
#endif

#if defined(_WIN32) && !defined(SKGL__APIENTRY)
#define SKGL__APIENTRY __stdcall
#elif !defined(SKGL__APIENTRY)
#define SKGL__APIENTRY
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* THE MAP of this implementation. Each anchor is a line of its own,
   "// >>name", where the part it names begins: search for "// >>name".
   Numbers are the sections' banners; shadowkit.h numbers its sections
   the same where it has the math of the same technique (6.2, 6.3, 6.4, 7,
   9); the other numbers are the GL side's own.
     1. The GL loader and enums ................................ >>loader
     2. What the context keeps ................................. >>context_data
     3. Saved state: the per-call tracker ...................... >>state
     4. The context ............................................ >>context
        4.1 the error log ...................................... >>log
            what a technique needs of the context .............. >>needs
            a call's arguments ................................. >>args
            the camera's depth convention ...................... >>camera
        4.2 uniforms, 4.3 the user's textures, 4.4 GPU timers,
        4.5 read-back rings, 4.6 the context's lifetime
            what the context offers (skgl_caps) ................ >>caps
     5. Shared pass helpers .................................... >>passes
            the lights' lifecycle .............................. >>lifecycle
        5.1 the lights' objects, 5.2 large worlds, 5.3 the draw
            callback; the one caster pass ...................... >>caster_pass
            layered single-pass rendering ...................... >>layered
            caster programs .................................... >>casters
        5.4 the masks' inputs
     6. Directional lights ..................................... >>shadow
            what differs from technique to technique ........... >>techniques
        6.1 the light: desc, create, destroy ................... >>shadow_life
        6.2 fits: PSSM, PSM, LiSPSM, LSPSM ..................... >>fits
            AUTO: the library chooses (CHOOSING FOR YOU) ....... >>auto
        6.3 FERKO's resolution estimation ...................... >>ferko
        6.4 RMSM's pages ....................................... >>rmsm
        6.5 the cache (CACHED MAPS) ............................ >>cache
            RMSM's page cache .................................. >>rmsm_cache
        6.6 analyze and render ................................. >>render
            the filterable map: EVSM's moments ................. >>evsm
        6.7 bind (forward shaders) ............................. >>bind
        6.8 the deferred mask .................................. >>mask
     7. Point lights: cube maps and VSDCT ...................... >>point
            the faces' cache ................................... >>point_cache
            spot lights: one perspective map in a cone ......... >>spot
     8. Several point lights in one atlas ...................... >>atlas
     9. Area lights: PCSS and PVSM: the frame timer, the light,
        its frustum, the passes ................................ >>soft
    10. Embedded GLSL, behind skgl__glsl() ..................... >>glsl
*/

/* ---- 1. The GL loader and enums ----------------------------------------- */
// >>loader
/* the GL 3.3 core subset shadowkit uses, loaded through the getproc */
typedef unsigned int skgl__enum;
typedef unsigned int skgl__uint;
typedef int skgl__int;
typedef int skgl__sizei;
typedef unsigned char skgl__bool;
typedef unsigned long long skgl__u64;

#define SKGL__DEPTH_BUFFER_BIT 0x0100
#define SKGL__TRIANGLES 0x0004
#define SKGL__LESS 0x0201
#define SKGL__LOWER_LEFT 0x8CA1
#define SKGL__NEGATIVE_ONE_TO_ONE 0x935E
#define SKGL__ZERO_TO_ONE 0x935F
#define SKGL__LEQUAL 0x0203
#define SKGL__CULL_FACE 0x0B44
#define SKGL__CULL_FACE_MODE 0x0B45
#define SKGL__DEPTH_TEST 0x0B71
#define SKGL__DEPTH_WRITEMASK 0x0B72
#define SKGL__DEPTH_CLEAR_VALUE 0x0B73
#define SKGL__DEPTH_FUNC 0x0B74
#define SKGL__VIEWPORT 0x0BA2
#define SKGL__BLEND 0x0BE2
#define SKGL__SCISSOR_BOX 0x0C10
#define SKGL__SCISSOR_TEST 0x0C11
#define SKGL__COLOR_WRITEMASK 0x0C23
#define SKGL__TEXTURE_2D 0x0DE1
#define SKGL__TEXTURE_WIDTH 0x1000
#define SKGL__TEXTURE_HEIGHT 0x1001
#define SKGL__FLOAT 0x1406
#define SKGL__DEPTH_COMPONENT 0x1902
#define SKGL__NEAREST 0x2600
#define SKGL__LINEAR 0x2601
#define SKGL__TEXTURE_MAG_FILTER 0x2800
#define SKGL__TEXTURE_MIN_FILTER 0x2801
#define SKGL__TEXTURE_WRAP_S 0x2802
#define SKGL__TEXTURE_WRAP_T 0x2803
#define SKGL__POLYGON_OFFSET_UNITS 0x2A00
#define SKGL__POLYGON_OFFSET_FILL 0x8037
#define SKGL__POLYGON_OFFSET_FACTOR 0x8038
#define SKGL__TEXTURE_BINDING_2D 0x8069
#define SKGL__CLAMP_TO_EDGE 0x812F
#define SKGL__TEXTURE0 0x84C0
#define SKGL__ACTIVE_TEXTURE 0x84E0
#define SKGL__VERTEX_ARRAY_BINDING 0x85B5
#define SKGL__QUERY_RESULT 0x8866
#define SKGL__TEXTURE_COMPARE_MODE 0x884C
#define SKGL__TEXTURE_COMPARE_FUNC 0x884D
#define SKGL__COMPARE_REF_TO_TEXTURE 0x884E
#define SKGL__TIME_ELAPSED 0x88BF
#define SKGL__SAMPLER_BINDING 0x8919
#define SKGL__FRAGMENT_SHADER 0x8B30
#define SKGL__VERTEX_SHADER 0x8B31
#define SKGL__COMPILE_STATUS 0x8B81
#define SKGL__LINK_STATUS 0x8B82
#define SKGL__CURRENT_PROGRAM 0x8B8D
#define SKGL__TEXTURE_2D_ARRAY 0x8C1A
#define SKGL__TEXTURE_BINDING_2D_ARRAY 0x8C1D
#define SKGL__DEPTH_COMPONENT32F 0x8CAC
#define SKGL__DRAW_FRAMEBUFFER_BINDING 0x8CA6
#define SKGL__READ_FRAMEBUFFER 0x8CA8
#define SKGL__DRAW_FRAMEBUFFER 0x8CA9
#define SKGL__READ_FRAMEBUFFER_BINDING 0x8CAA
#define SKGL__FRAMEBUFFER_COMPLETE 0x8CD5
#define SKGL__COLOR_ATTACHMENT0 0x8CE0
#define SKGL__DEPTH_ATTACHMENT 0x8D00
#define SKGL__FRAMEBUFFER 0x8D40
#define SKGL__MAJOR_VERSION 0x821B
#define SKGL__MINOR_VERSION 0x821C
#define SKGL__NONE 0
#define SKGL__RGBA 0x1908
#define SKGL__RGBA32F 0x8814
#define SKGL__PIXEL_PACK_BUFFER 0x88EB
#define SKGL__PIXEL_PACK_BUFFER_BINDING 0x88ED
#define SKGL__STREAM_READ 0x88E1
#define SKGL__COLOR_ATTACHMENT1 0x8CE1
#define SKGL__RGBA8 0x8058
#define SKGL__UNSIGNED_BYTE 0x1401
#define SKGL__POINTS 0x0000
#define SKGL__PROGRAM_POINT_SIZE 0x8642
#define SKGL__COLOR_BUFFER_BIT 0x4000
#define SKGL__COLOR_CLEAR_VALUE 0x0C22
#define SKGL__PIXEL_UNPACK_BUFFER 0x88EC
#define SKGL__PIXEL_UNPACK_BUFFER_BINDING 0x88EF
#define SKGL__TEXTURE_CUBE_MAP 0x8513
#define SKGL__TEXTURE_BINDING_CUBE_MAP 0x8514
#define SKGL__TEXTURE_CUBE_MAP_POSITIVE_X 0x8515
#define SKGL__TEXTURE_CUBE_MAP_SEAMLESS 0x884F
#define SKGL__TEXTURE_BASE_LEVEL 0x813C
#define SKGL__TEXTURE_MAX_LEVEL 0x813D
#define SKGL__TEXTURE_WRAP_R 0x8072
#define SKGL__RG 0x8227
#define SKGL__RG16 0x822C
#define SKGL__UNSIGNED_SHORT 0x1403
#define SKGL__GEOMETRY_SHADER 0x8DD9
#define SKGL__VERSION 0x1F02
#define SKGL__EXTENSIONS 0x1F03
#define SKGL__NUM_EXTENSIONS 0x821D
#define SKGL__MAX_TEXTURE_SIZE 0x0D33
#define SKGL__MAP_READ_BIT 0x0001
#define SKGL__GPU_DISJOINT 0x8FBB
/* GLSL ES: no default precision for floats in fragment shaders, nor for
   the array, shadow and integer samplers in any stage; highp everywhere
   (the depth comparisons need 24 bits and more) */
#define SKGL__ES_PRECISION                                                                          \
    "precision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"                   \
    "precision highp sampler2DArray;\nprecision highp sampler2DShadow;\n"                          \
    "precision highp sampler2DArrayShadow;\nprecision highp samplerCube;\n"                        \
    "precision highp samplerCubeShadow;\nprecision highp isampler2D;\nprecision highp usampler2D;\n" \
    "precision highp sampler3D;\n#define SKGL_ES 1\n"
#define SKGL__BLEND_EQUATION_RGB 0x8009
#define SKGL__BLEND_EQUATION_ALPHA 0x883D
#define SKGL__BLEND_DST_RGB 0x80C8
#define SKGL__BLEND_SRC_RGB 0x80C9
#define SKGL__BLEND_DST_ALPHA 0x80CA
#define SKGL__BLEND_SRC_ALPHA 0x80CB
#define SKGL__FUNC_ADD 0x8006
#define SKGL__MIN 0x8007
#define SKGL__ONE 1
#define SKGL__DEPTH_CLAMP 0x864F
#define SKGL__R32F 0x822E
#define SKGL__RG32F 0x8230
#define SKGL__RED 0x1903
#define SKGL__RGBA16F 0x881A
#define SKGL__NEAREST_MIPMAP_NEAREST 0x2700
#define SKGL__COLOR_ATTACHMENT2 0x8CE2
#define SKGL__UNITS 5                      /* texture units the mask pass uses: 0 .. 4 (4: EVSM's moments) */
#define SKGL__POLYGON_MODE 0x0B40
#define SKGL__FRONT_AND_BACK 0x0408
#define SKGL__FILL 0x1B02
#define SKGL__COLOR 0x1800                 /* glClearBufferfv's buffers */
#define SKGL__DEPTH 0x1801
#define SKGL__R8 0x8229
#define SKGL__QUERY_RESULT_AVAILABLE 0x8867
#define SKGL__ACTIVE_UNIFORMS 0x8B86
#define SKGL__SYNC_GPU_COMMANDS_COMPLETE 0x9117
#define SKGL__SYNC_FLUSH_COMMANDS_BIT 0x00000001
#define SKGL__ALREADY_SIGNALED 0x911A
#define SKGL__CONDITION_SATISFIED 0x911C
#define SKGL__PACK_ALIGNMENT 0x0D05
#define SKGL__PACK_ROW_LENGTH 0x0D02
#define SKGL__PACK_SKIP_ROWS 0x0D03
#define SKGL__PACK_SKIP_PIXELS 0x0D04
#define SKGL__UNPACK_ALIGNMENT 0x0CF5
#define SKGL__UNPACK_ROW_LENGTH 0x0CF2
#define SKGL__UNPACK_SKIP_ROWS 0x0CF3
#define SKGL__UNPACK_SKIP_PIXELS 0x0CF4

#define SKGL__FUNCS(X) \
    X(skgl__enum, GetError, (void)) \
    X(void, Finish, (void)) \
    X(void, GetIntegerv, (skgl__enum pname, skgl__int *data)) \
    X(void, GetFloatv, (skgl__enum pname, float *data)) \
    X(void, GetBooleanv, (skgl__enum pname, skgl__bool *data)) \
    X(skgl__bool, IsEnabled, (skgl__enum cap)) \
    X(void, Enable, (skgl__enum cap)) \
    X(void, Disable, (skgl__enum cap)) \
    X(void, Viewport, (skgl__int x, skgl__int y, skgl__sizei w, skgl__sizei h)) \
    X(void, Scissor, (skgl__int x, skgl__int y, skgl__sizei w, skgl__sizei h)) \
    X(void, ColorMask, (skgl__bool r, skgl__bool g, skgl__bool b, skgl__bool a)) \
    X(void, DepthMask, (skgl__bool flag)) \
    X(void, DepthFunc, (skgl__enum func)) \
    X(void, PolygonOffset, (float factor, float units)) \
    X(void, GenFramebuffers, (skgl__sizei n, skgl__uint *ids)) \
    X(void, DeleteFramebuffers, (skgl__sizei n, const skgl__uint *ids)) \
    X(void, BindFramebuffer, (skgl__enum target, skgl__uint fb)) \
    X(void, FramebufferTextureLayer, (skgl__enum target, skgl__enum att, skgl__uint tex, skgl__int level, skgl__int layer)) \
    X(void, FramebufferTexture2D, (skgl__enum target, skgl__enum att, skgl__enum textarget, skgl__uint tex, skgl__int level)) \
    X(skgl__enum, CheckFramebufferStatus, (skgl__enum target)) \
    X(void, ReadBuffer, (skgl__enum buf)) \
    X(void, GenTextures, (skgl__sizei n, skgl__uint *ids)) \
    X(void, DeleteTextures, (skgl__sizei n, const skgl__uint *ids)) \
    X(void, BindTexture, (skgl__enum target, skgl__uint tex)) \
    X(void, ActiveTexture, (skgl__enum unit)) \
    X(void, TexImage2D, (skgl__enum target, skgl__int level, skgl__int ifmt, skgl__sizei w, skgl__sizei h, skgl__int border, skgl__enum fmt, skgl__enum type, const void *data)) \
    X(void, ReadPixels, (skgl__int x, skgl__int y, skgl__sizei w, skgl__sizei h, skgl__enum fmt, skgl__enum type, void *data)) \
    X(void, DrawBuffers, (skgl__sizei n, const skgl__enum *bufs)) \
    X(void, GenBuffers, (skgl__sizei n, skgl__uint *ids)) \
    X(void, DeleteBuffers, (skgl__sizei n, const skgl__uint *ids)) \
    X(void, BindBuffer, (skgl__enum target, skgl__uint buf)) \
    X(void, BufferData, (skgl__enum target, ptrdiff_t size, const void *data, skgl__enum usage)) \
    X(void, Uniform2i, (skgl__int loc, skgl__int a, skgl__int b)) \
    X(void, Uniform4fv, (skgl__int loc, skgl__sizei n, const float *v)) \
    X(void, Uniform2fv, (skgl__int loc, skgl__sizei n, const float *v)) \
    X(void, PixelStorei, (skgl__enum pname, skgl__int v)) \
    X(void, TexImage3D, (skgl__enum target, skgl__int level, skgl__int ifmt, skgl__sizei w, skgl__sizei h, skgl__sizei d, skgl__int border, skgl__enum fmt, skgl__enum type, const void *data)) \
    X(void, TexParameteri, (skgl__enum target, skgl__enum pname, skgl__int v)) \
    X(void, GenSamplers, (skgl__sizei n, skgl__uint *ids)) \
    X(void, DeleteSamplers, (skgl__sizei n, const skgl__uint *ids)) \
    X(void, BindSampler, (skgl__uint unit, skgl__uint sampler)) \
    X(void, SamplerParameteri, (skgl__uint sampler, skgl__enum pname, skgl__int v)) \
    X(skgl__uint, CreateShader, (skgl__enum type)) \
    X(void, ShaderSource, (skgl__uint sh, skgl__sizei n, const char *const *src, const skgl__int *len)) \
    X(void, CompileShader, (skgl__uint sh)) \
    X(void, GetShaderiv, (skgl__uint sh, skgl__enum pname, skgl__int *v)) \
    X(void, GetShaderInfoLog, (skgl__uint sh, skgl__sizei max, skgl__sizei *len, char *log)) \
    X(void, DeleteShader, (skgl__uint sh)) \
    X(skgl__uint, CreateProgram, (void)) \
    X(void, AttachShader, (skgl__uint p, skgl__uint sh)) \
    X(void, LinkProgram, (skgl__uint p)) \
    X(void, GetProgramiv, (skgl__uint p, skgl__enum pname, skgl__int *v)) \
    X(void, GetProgramInfoLog, (skgl__uint p, skgl__sizei max, skgl__sizei *len, char *log)) \
    X(void, DeleteProgram, (skgl__uint p)) \
    X(void, UseProgram, (skgl__uint p)) \
    X(skgl__int, GetUniformLocation, (skgl__uint p, const char *name)) \
    X(void, Uniform1i, (skgl__int loc, skgl__int v)) \
    X(void, Uniform1iv, (skgl__int loc, skgl__sizei n, const skgl__int *v)) \
    X(void, Uniform1f, (skgl__int loc, float v)) \
    X(void, Uniform1fv, (skgl__int loc, skgl__sizei n, const float *v)) \
    X(void, Uniform3fv, (skgl__int loc, skgl__sizei n, const float *v)) \
    X(void, UniformMatrix4fv, (skgl__int loc, skgl__sizei n, skgl__bool transpose, const float *v)) \
    X(void, GenVertexArrays, (skgl__sizei n, skgl__uint *ids)) \
    X(void, DeleteVertexArrays, (skgl__sizei n, const skgl__uint *ids)) \
    X(void, BindVertexArray, (skgl__uint vao)) \
    X(void, DrawArrays, (skgl__enum mode, skgl__int first, skgl__sizei count)) \
    X(void, GenQueries, (skgl__sizei n, skgl__uint *ids)) \
    X(void, DeleteQueries, (skgl__sizei n, const skgl__uint *ids)) \
    X(void, BeginQuery, (skgl__enum target, skgl__uint id)) \
    X(void, EndQuery, (skgl__enum target)) \
    X(void, BlendEquationSeparate, (skgl__enum rgb, skgl__enum alpha)) \
    X(void, BlendFuncSeparate, (skgl__enum src_rgb, skgl__enum dst_rgb, skgl__enum src_a, skgl__enum dst_a)) \
    X(skgl__bool, IsProgram, (skgl__uint p)) \
    X(skgl__bool, IsTexture, (skgl__uint t)) \
    X(void, ClearBufferfv, (skgl__enum buffer, skgl__int drawbuffer, const float *value)) \
    X(void, BlitFramebuffer, (skgl__int sx0, skgl__int sy0, skgl__int sx1, skgl__int sy1, skgl__int dx0, skgl__int dy0, skgl__int dx1, skgl__int dy1, skgl__uint mask, skgl__enum filter)) \
    X(void, TexSubImage2D, (skgl__enum target, skgl__int level, skgl__int x, skgl__int y, skgl__sizei w, skgl__sizei h, skgl__enum fmt, skgl__enum type, const void *data)) \
    X(void *, FenceSync, (skgl__enum condition, skgl__uint flags)) \
    X(skgl__enum, ClientWaitSync, (void *sync, skgl__uint flags, skgl__u64 timeout)) \
    X(void, DeleteSync, (void *sync)) \
    X(void, GetQueryObjectuiv, (skgl__uint id, skgl__enum pname, skgl__uint *v)) \
    X(void, GetUniformiv, (skgl__uint p, skgl__int loc, skgl__int *v)) \
    X(void, GetUniformfv, (skgl__uint p, skgl__int loc, float *v)) \
    X(const unsigned char *, GetString, (skgl__enum name)) \
    X(const unsigned char *, GetStringi, (skgl__enum name, skgl__uint i))

/* entry points one API or extension has and another lacks: loaded by
   skgl_create where skgl_caps says they exist (the name may differ: ES's
   timer query is glGetQueryObjectui64vEXT), NULL elsewhere and never called
   there */
#define SKGL__FUNCS_OPT(X) \
    X(void, FramebufferTexture, (skgl__enum target, skgl__enum att, skgl__uint tex, skgl__int level)) \
    X(void, GetBufferSubData, (skgl__enum target, ptrdiff_t offset, ptrdiff_t size, void *data)) \
    X(void, GetTexLevelParameteriv, (skgl__enum target, skgl__int level, skgl__enum pname, skgl__int *v)) \
    X(void, GetQueryObjectui64v, (skgl__uint id, skgl__enum pname, skgl__u64 *v)) \
    X(void, PolygonMode, (skgl__enum face, skgl__enum mode)) \
    X(void *, MapBufferRange, (skgl__enum target, ptrdiff_t offset, ptrdiff_t size, skgl__uint access)) \
    X(skgl__bool, UnmapBuffer, (skgl__enum target))

typedef struct skgl__api {
#define SKGL__X(ret, name, args) ret (SKGL__APIENTRY *name) args;
    SKGL__FUNCS(SKGL__X)
    SKGL__FUNCS_OPT(SKGL__X)
#undef SKGL__X
} skgl__api;

/* the embedded sources (section 10), by name: skgl__glsl(SKGL__GLSL_DEPTH_VERT) */
typedef enum skgl__glsl_id {
    SKGL__GLSL_DEPTH_VERT,
    SKGL__GLSL_DEPTH_FRAG,
    SKGL__GLSL_FULLSCREEN_VERT,
    SKGL__GLSL_SHADOW_SAMPLE_GLSL,
    SKGL__GLSL_SHADOW_MASK_FRAG,
    SKGL__GLSL_FERKO_ANALYZE_FRAG,
    SKGL__GLSL_FERKO_REDUCE_FRAG,
    SKGL__GLSL_RMSM_ANALYZE_FRAG,
    SKGL__GLSL_RMSM_REQUEST_VERT,
    SKGL__GLSL_RMSM_REQUEST_FRAG,
    SKGL__GLSL_POINT_SAMPLE_GLSL,
    SKGL__GLSL_POINT_MASK_FRAG,
    SKGL__GLSL_SOFT_COMMON_GLSL,
    SKGL__GLSL_SOFT_KERNEL_FRAG,
    SKGL__GLSL_SOFT_SMTG_VERT,
    SKGL__GLSL_SOFT_SMTG_FRAG,
    SKGL__GLSL_SOFT_REDUCE_VERT,
    SKGL__GLSL_SOFT_REDUCE_FRAG,
    SKGL__GLSL_SOFT_FILTER_FRAG,
    SKGL__GLSL_SOFT_RESOLVE_FRAG,
    SKGL__GLSL_SOFT_CONS_GEOM,
    SKGL__GLSL_SOFT_CONS_FRAG,
    SKGL__GLSL_SOFT_GBUFFER_VERT,
    SKGL__GLSL_SOFT_GBUFFER_FRAG,
    SKGL__GLSL_PCSS_MASK_FRAG,
    SKGL__GLSL_LAYERED_GEOM,
    SKGL__GLSL_SOFT_DILATE_FRAG,
    SKGL__GLSL_EVSM_MOMENTS_FRAG,
    SKGL__GLSL_N
} skgl__glsl_id;
static const char *skgl__glsl(skgl__glsl_id id);

/* ---- 2. What the context keeps between calls ---------------------------- */
// >>context_data
/* the caches, the timers and rings, the context */
#define SKGL__PROG_CACHE 16                /* user programs whose snippet locations are cached */
#define SKGL__TEX_CACHE 8                  /* user textures whose size / framebuffer check is cached */
#define SKGL__TIMER_RING 3                 /* timer queries per timed pass, read two or three frames late */
#define SKGL__RING 3                       /* pixel pack buffers per late read-back */
#define SKGL__FERKO_LEVELS 5               /* analysis + reductions, for G-buffers up to 65536 a side */
#define SKGL__LOCS 23                      /* the most snippet uniforms (the directional one's, EVSM's included) */
enum { SKGL__PK_SHADOW = 0, SKGL__PK_POINT = 1 };

/* a program holding a GLSL snippet (skgl__progent_lookup) */
typedef struct skgl__progent {
    skgl__uint program;                    /* 0: a free entry */
    int kind;                              /* SKGL__PK_SHADOW, SKGL__PK_POINT */
    char prefix[SKGL_PREFIX_MAX + 1];      /* the snippet's names start with this ("": sk_) */
    unsigned tick;                         /* last use: the least recent goes first */
    skgl__int loc[SKGL__LOCS];
    skgl__int uniforms;                    /* GL_ACTIVE_UNIFORMS at look-up (the default mode's check) */
    unsigned owner;                        /* the light whose constants the program holds (0: none) */
    int unit;                              /* the texture unit those name */
    skgl__int sentinel_i;                  /* sk_rmsm_page / sk_point_range as last set (the debug check) */
    float sentinel_f;
    /* uniforms that seldom change, as last sent (valid while owner is set) */
    int layers, min_level, has_normals;
    float extent[2], select, texel;
    unsigned layout;
    /* the forward contact march's uniforms (SK_SHADOW_CONTACT), looked up
       at the program's first bind: depth sampler, sk_contact,
       sk_contact_camera, sk_contact_depth_map; the sampler's unit as set
       (-1: not yet), and whether the program's march is on */
    int contact_looked, contact_unit, contact_on;
    skgl__int contact_loc[4];
} skgl__progent;

/* The directional mask program compiled with EVSM (SK_SHADOW_EVSM), made
   with the first EVSM light: its own locations and sent values, swapped
   with the context's mask_* fields for an EVSM light's mask
   (skgl__mask_swap), so that the PCF mask program stays as it was */
typedef struct skgl__mask_prog {
    skgl__uint prog;
    skgl__progent ent;
    skgl__int u_has_normals, u_camera, u_contact, u_view_proj, u_depth_map;
    float contact[4], dmap[4];
} skgl__mask_prog;

typedef struct skgl__texent {
    skgl__uint tex;                        /* 0: a free entry */
    unsigned tick;
    int w, h;                              /* level 0, as GL had it (0: not asked) */
    int fb_ok;                             /* 1: checked complete as a mask target */
    int named;                             /* 1: glIsTexture said it is a texture */
} skgl__texent;

typedef struct skgl__timer {
    skgl__uint q[SKGL__TIMER_RING];        /* 0 without desc.timing */
    unsigned char pending[SKGL__TIMER_RING];
    unsigned frame;                        /* passes timed so far; slot frame % ring next */
    int running;
    float ms;                              /* the latest result read; -1 before any */
} skgl__timer;

typedef struct skgl__ring {
    skgl__uint buf[SKGL__RING];            /* GL_PIXEL_PACK_BUFFERs of `bytes` each */
    void *sync[SKGL__RING];                /* the fence after the read-back into buf[i]; NULL: free */
    size_t bytes;
    int next;                              /* the slot the next read-back takes */
    /* what each read-back is of: the light frustum and origin of its analysis */
    sk_mat4 lvp[SKGL__RING];
    double origin[SKGL__RING][3];
} skgl__ring;

/* the kinds of caster pass a caster program is linked for (5.3, caster programs) */
enum { SKGL__CV_DEPTH = 0, SKGL__CV_CONS = 1, SKGL__CV_GBUF = 2, SKGL__CV_LAYERED = 3, SKGL__CV_COUNT = 4 };

/* which of the scene's callbacks a caster pass calls (CACHED MAPS) */
#define SKGL__DRAW_ALL 0              /* draw, then the dynamic casters (skgl_set_dynamic) */
#define SKGL__DRAW_STATIC 1           /* draw only: into a cache */
#define SKGL__DRAW_DYNAMIC 2          /* the dynamic casters only: over a cached map */

struct skgl_context {
    skgl__api gl;
    skgl_caps caps;                        /* probed at create, less desc.disable_caps */
    const char *glsl_version;              /* the dialect's first lines (skgl__shader_n) */
    int debug, timing, objects;
    int draw_class;                        /* SKGL__DRAW_*: the callbacks the next caster passes call */
    skgl_dynamic dyn;                      /* skgl_set_dynamic's (draw NULL: none) */
    int caller_owns;                       /* desc.caller_owns_state: no reads, no restore */
    int clip_zero_to_one;                  /* desc.clip_zero_to_one */
    void (SKGL__APIENTRY *ClipControl)(skgl__enum origin, skgl__enum depth);   /* with it: GL 4.5 */
    skgl__uint depth_prog, mask_prog, empty_vao;
    skgl__uint mask_fbo;                   /* the deferred masks' target: the mask texture attached per call */
    skgl__uint mask_fbo_tex;               /* the texture attached to it now (0: none) */
    skgl__uint cmp_sampler, point_sampler;
    /* made with the first light that needs them (skgl__ferko_programs, skgl__rmsm_programs) */
    skgl__uint ferko_prog, reduce_prog;    /* resolution estimation: analysis, 16x16 MIN reduction */
    skgl__uint final_prog;                 /* resolution estimation: the last reduction, into 2x1 texels */
    skgl__uint rmsm_prog, request_prog;    /* RMSM: per-pixel samples, page-request scatter */
    skgl__int depth_u_view_proj, depth_u_model;
    skgl__uint pass_prog;                  /* the current caster pass's program (depth_prog, or an area
                                              light's low-res or G-buffer program) */
    skgl__int pass_vp_loc;                 /* its skgl_view_proj */
    skgl__int pass_model_loc;              /* its skgl_model */
    skgl__int model_loc;                   /* where skgl_set_model writes: the current program's skgl_model */
    int model_dirty;                       /* skgl_set_model was called on the pass's program since
                                              the pass set its model */
    /* caster programs (skgl_use_caster): what a caster's program for this
       pass needs, kept when the pass begins and at each callback */
    int pass_variant;                      /* SKGL__CV_DEPTH, _CONS, _GBUF */
    unsigned pass_serial;                  /* counts callbacks: a caster program sent this one's matrix */
    float pass_vp[16];                     /* the pass's view-projection (relative to its origin) */
    float pass_texel[2];                   /* SKGL__CV_CONS: skgl_texel */
    int pass_conservative;                 /* SKGL__CV_CONS: skgl_conservative */
    float pass_eye[3];                     /* SKGL__CV_GBUF: skgl_eye */
    struct skgl_caster *casters;           /* every caster made, freed with the context */
    struct skgl_caster *cur_caster;        /* bound by the callback now (NULL: the pass's program) */
    sk_result pass_error;                  /* a caster program that failed to link in this callback */
    /* layered passes (5.3): the depth program with layered.geom, made
       on first use; the layers of the pass under way */
    skgl__uint layered_prog;
    int layered_state;                     /* 0 not tried, 1 loop, 2 invocations, -1 no program */
    skgl__int layered_u_model, layered_u_vp, layered_u_of, layered_u_count;
    int pass_layers;                       /* 0: the pass draws one layer */
    float pass_layer_vp[SKGL_MAX_CASCADES][16];
    int pass_layer_of[SKGL_MAX_CASCADES];
    double model_origin[3];        /* skgl_set_model during a directional pass: models move to this origin */
    /* the locations of shadowkit's own programs, found at link time, and the
       values of the uniforms that seldom change, as last sent */
    skgl__progent mask_ent;                /* the directional mask's snippet uniforms */
    skgl__int mask_u_has_normals, mask_u_camera;
    skgl__int mask_u_contact, mask_u_view_proj;   /* contact shadows: the march, the camera */
    float mask_contact[4];                 /* the march's values mask_prog holds (GL's 0 at first) */
    /* EVSM (FILTERABLE MAPS): the moments blur's horizontal [0] and vertical
       [1] programs, made with the first EVSM light, and their locations */
    skgl__uint evsm_prog[2];
    skgl__int evsm_u_box[2], evsm_u_extent[2], evsm_u_layer;
    skgl__mask_prog mask_evsm;
    /* u_depth_map (the camera's depth convention) of the mask and analysis
       programs, and the values last sent (the default convention's at link) */
    skgl__int mask_u_depth_map, ferko_u_depth_map, rmsm_u_depth_map;
    float mask_dmap[4], ferko_dmap[4], rmsm_dmap[4];
    float cam_dmap[4];                     /* the convention of the depth buffer the call under way reads */
    float cam_view_z[4];                   /* row 2 of its inverse projection (view depths, 6.3) */
    float ferko_view_z[4];                 /* the one ferko_prog holds */
    skgl__int ferko_u_ndc_to_light, ferko_u_world_w, ferko_u_view_z, ferko_u_depth_only, reduce_u_src_size,
        final_u_src_size;
    int ferko_depth_only;                  /* the value ferko_prog holds (-1: not sent) */
    skgl__int rmsm_u_inv_view_proj, rmsm_u_light, rmsm_u_virtual_res, request_u_pages0, request_u_levels;
    skgl__int request_u_bands;
    int reduce_src[2], final_src[2], request_pages0, request_levels, request_bands;
    float rmsm_vres;
    skgl__progent progs[SKGL__PROG_CACHE]; /* the user's programs (skgl_*_bind) */
    skgl__texent texs[SKGL__TEX_CACHE];    /* the user's mask and depth textures */
    unsigned tick;                         /* cache use counter */
    unsigned next_id;                      /* the id of the next light made (never 0) */
    char log[1024];
    skgl_logger logger;                    /* desc.logger: each message of log as it is written */
    int log_quiet;                         /* > 0: messages of a try that may fail are not logged */
    int failed;                            /* the log holds this call's error (not a warning) */
    const char *stage;                     /* desc.debug: the pass under way, for the GL error's message */
    const char *call;                      /* the public call under way (skgl__enter) */
    int prog_unsure;                       /* a callback returned with debug off: the pass's
                                              program is bound again before its next uniform */
};


/* ---- 3. Saved state ----------------------------------------------------- */
// >>state
static void skgl__enable(const skgl__api *gl, skgl__enum cap, int on)
{
    if (on) gl->Enable(cap); else gl->Disable(cap);
}

/* the state one call touches --------------------------------------
   Directional and point lights go through this tracker instead of a full
   save and restore: each piece of state is set through skgl__st_set, which
   (default mode) reads the caller's value the first time the call touches
   it, and skips the set when the value is already there; skgl__st_end puts
   back only what changed, in as few calls as it can (one glBindFramebuffer
   for both targets when they were the same, the texture units ending on the
   one the caller had active). With skgl_desc.caller_owns_state nothing is
   read: the first set of each piece is unconditional, later ones within the
   call are skipped when redundant, and skgl__st_end unbinds only what would
   redirect the caller's own later calls into shadowkit's objects (the
   framebuffers, the pixel pack and unpack buffers). Everything else stays
   as the manual's GL STATE section lists. */
enum {
    SKGL__S_DRAW_FB, SKGL__S_READ_FB, SKGL__S_VIEWPORT, SKGL__S_SCISSOR_BOX,
    SKGL__S_SCISSOR_TEST, SKGL__S_BLEND, SKGL__S_CULL_FACE, SKGL__S_DEPTH_TEST, SKGL__S_POLY_FILL,
    SKGL__S_POINT_SIZE, SKGL__S_SEAMLESS, SKGL__S_DEPTH_CLAMP,
    SKGL__S_DEPTH_FUNC, SKGL__S_DEPTH_MASK, SKGL__S_COLOR_MASK, SKGL__S_POLY_OFFSET, SKGL__S_POLYGON_MODE,
    SKGL__S_BLEND_EQ, SKGL__S_BLEND_FUNC,
    SKGL__S_PROGRAM, SKGL__S_VAO, SKGL__S_PACK_BUFFER, SKGL__S_UNPACK_BUFFER,
    SKGL__S_PACK_ALIGNMENT, SKGL__S_PACK_ROW_LENGTH, SKGL__S_PACK_SKIP_PIXELS, SKGL__S_PACK_SKIP_ROWS,
    SKGL__S_UNPACK_ALIGNMENT, SKGL__S_UNPACK_ROW_LENGTH, SKGL__S_UNPACK_SKIP_PIXELS, SKGL__S_UNPACK_SKIP_ROWS,
    SKGL__S_ACTIVE,
    SKGL__S_UNIT0,                        /* unit u: + 4 u + (0 2D, 1 2D array, 2 cube map, 3 sampler) */
    SKGL__S_COUNT = SKGL__S_UNIT0 + 4 * SKGL__UNITS
};
#define SKGL__S_TEX(u, k) (SKGL__S_UNIT0 + 4 * (u) + (k))
#define SKGL__T_2D 0
#define SKGL__T_2D_ARRAY 1
#define SKGL__T_CUBE 2
#define SKGL__T_SAMPLER 3

#define SKGL__S_KNOWN 1u                  /* cur holds GL's value */
#define SKGL__S_SAVED 2u                  /* orig holds the caller's value (default mode) */

typedef struct skgl__st {
    int restore;                          /* 1: default mode, read and put back */
    unsigned char flags[SKGL__S_COUNT];
    skgl__int cur[SKGL__S_COUNT][4], orig[SKGL__S_COUNT][4];
} skgl__st;

static int skgl__st_n(int item)
{
    return item == SKGL__S_VIEWPORT || item == SKGL__S_SCISSOR_BOX || item == SKGL__S_COLOR_MASK ||
                   item == SKGL__S_BLEND_FUNC ? 4
           : item == SKGL__S_POLY_OFFSET || item == SKGL__S_BLEND_EQ ? 2 : 1;
}

static skgl__enum skgl__st_cap(int item)
{
    switch (item) {
    case SKGL__S_SCISSOR_TEST: return SKGL__SCISSOR_TEST;
    case SKGL__S_BLEND: return SKGL__BLEND;
    case SKGL__S_CULL_FACE: return SKGL__CULL_FACE;
    case SKGL__S_DEPTH_TEST: return SKGL__DEPTH_TEST;
    case SKGL__S_POLY_FILL: return SKGL__POLYGON_OFFSET_FILL;
    case SKGL__S_POINT_SIZE: return SKGL__PROGRAM_POINT_SIZE;
    case SKGL__S_SEAMLESS: return SKGL__TEXTURE_CUBE_MAP_SEAMLESS;
    case SKGL__S_DEPTH_CLAMP: return SKGL__DEPTH_CLAMP;
    default: return 0;
    }
}

static skgl__enum skgl__st_store_name(int item)
{
    static const skgl__enum names[8] = {SKGL__PACK_ALIGNMENT, SKGL__PACK_ROW_LENGTH, SKGL__PACK_SKIP_PIXELS,
                                        SKGL__PACK_SKIP_ROWS, SKGL__UNPACK_ALIGNMENT, SKGL__UNPACK_ROW_LENGTH,
                                        SKGL__UNPACK_SKIP_PIXELS, SKGL__UNPACK_SKIP_ROWS};
    return names[item - SKGL__S_PACK_ALIGNMENT];
}

static const skgl__enum skgl__tex_targets[3] = {SKGL__TEXTURE_2D, SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_CUBE_MAP};
static const skgl__enum skgl__tex_bindings[4] = {SKGL__TEXTURE_BINDING_2D, SKGL__TEXTURE_BINDING_2D_ARRAY,
                                                 SKGL__TEXTURE_BINDING_CUBE_MAP, SKGL__SAMPLER_BINDING};

/* GL's value of an item (a unit's item: with that unit active) */
static void skgl__st_query(const skgl__api *gl, int item, skgl__int v[4])
{
    skgl__bool b[4] = {0, 0, 0, 0};
    float f[2];
    skgl__int mode[2] = {SKGL__FILL, SKGL__FILL};
    if (skgl__st_cap(item)) { v[0] = gl->IsEnabled(skgl__st_cap(item)) != 0; return; }
    if (item >= SKGL__S_PACK_ALIGNMENT && item <= SKGL__S_UNPACK_SKIP_ROWS) {
        gl->GetIntegerv(skgl__st_store_name(item), v);
        return;
    }
    if (item >= SKGL__S_UNIT0) { gl->GetIntegerv(skgl__tex_bindings[(item - SKGL__S_UNIT0) & 3], v); return; }
    switch (item) {
    case SKGL__S_DRAW_FB: gl->GetIntegerv(SKGL__DRAW_FRAMEBUFFER_BINDING, v); break;
    case SKGL__S_READ_FB: gl->GetIntegerv(SKGL__READ_FRAMEBUFFER_BINDING, v); break;
    case SKGL__S_VIEWPORT: gl->GetIntegerv(SKGL__VIEWPORT, v); break;
    case SKGL__S_SCISSOR_BOX: gl->GetIntegerv(SKGL__SCISSOR_BOX, v); break;
    case SKGL__S_DEPTH_FUNC: gl->GetIntegerv(SKGL__DEPTH_FUNC, v); break;
    case SKGL__S_DEPTH_MASK: gl->GetBooleanv(SKGL__DEPTH_WRITEMASK, b); v[0] = b[0] != 0; break;
    case SKGL__S_COLOR_MASK:
        gl->GetBooleanv(SKGL__COLOR_WRITEMASK, b);
        v[0] = b[0] != 0; v[1] = b[1] != 0; v[2] = b[2] != 0; v[3] = b[3] != 0;
        break;
    case SKGL__S_POLY_OFFSET:
        /* floats kept bit for bit in the int slots */
        gl->GetFloatv(SKGL__POLYGON_OFFSET_FACTOR, &f[0]);
        gl->GetFloatv(SKGL__POLYGON_OFFSET_UNITS, &f[1]);
        memcpy(v, f, sizeof f);
        break;
    case SKGL__S_POLYGON_MODE:
        /* GL_POLYGON_MODE answers two values (front, back) in compatibility
           contexts, and a core context's are equal (only GL_FRONT_AND_BACK
           can be set): room for two, the first kept */
        gl->GetIntegerv(SKGL__POLYGON_MODE, mode);
        v[0] = mode[0];
        break;
    case SKGL__S_BLEND_EQ:
        gl->GetIntegerv(SKGL__BLEND_EQUATION_RGB, &v[0]);
        gl->GetIntegerv(SKGL__BLEND_EQUATION_ALPHA, &v[1]);
        break;
    case SKGL__S_BLEND_FUNC:
        gl->GetIntegerv(SKGL__BLEND_SRC_RGB, &v[0]);
        gl->GetIntegerv(SKGL__BLEND_DST_RGB, &v[1]);
        gl->GetIntegerv(SKGL__BLEND_SRC_ALPHA, &v[2]);
        gl->GetIntegerv(SKGL__BLEND_DST_ALPHA, &v[3]);
        break;
    case SKGL__S_PROGRAM: gl->GetIntegerv(SKGL__CURRENT_PROGRAM, v); break;
    case SKGL__S_VAO: gl->GetIntegerv(SKGL__VERTEX_ARRAY_BINDING, v); break;
    case SKGL__S_PACK_BUFFER: gl->GetIntegerv(SKGL__PIXEL_PACK_BUFFER_BINDING, v); break;
    case SKGL__S_UNPACK_BUFFER: gl->GetIntegerv(SKGL__PIXEL_UNPACK_BUFFER_BINDING, v); break;
    case SKGL__S_ACTIVE: gl->GetIntegerv(SKGL__ACTIVE_TEXTURE, v); break;
    default: break;
    }
}

/* sets an item in GL (a unit's texture binding: with that unit active) */
static void skgl__st_apply(const skgl__api *gl, int item, const skgl__int v[4])
{
    float f[2];
    if (skgl__st_cap(item)) { skgl__enable(gl, skgl__st_cap(item), v[0]); return; }
    if (item >= SKGL__S_PACK_ALIGNMENT && item <= SKGL__S_UNPACK_SKIP_ROWS) {
        gl->PixelStorei(skgl__st_store_name(item), v[0]);
        return;
    }
    if (item >= SKGL__S_UNIT0) {
        int k = (item - SKGL__S_UNIT0) & 3;
        if (k == SKGL__T_SAMPLER) gl->BindSampler((skgl__uint)((item - SKGL__S_UNIT0) >> 2), (skgl__uint)v[0]);
        else gl->BindTexture(skgl__tex_targets[k], (skgl__uint)v[0]);
        return;
    }
    switch (item) {
    case SKGL__S_DRAW_FB: gl->BindFramebuffer(SKGL__DRAW_FRAMEBUFFER, (skgl__uint)v[0]); break;
    case SKGL__S_READ_FB: gl->BindFramebuffer(SKGL__READ_FRAMEBUFFER, (skgl__uint)v[0]); break;
    case SKGL__S_VIEWPORT: gl->Viewport(v[0], v[1], v[2], v[3]); break;
    case SKGL__S_SCISSOR_BOX: gl->Scissor(v[0], v[1], v[2], v[3]); break;
    case SKGL__S_DEPTH_FUNC: gl->DepthFunc((skgl__enum)v[0]); break;
    case SKGL__S_DEPTH_MASK: gl->DepthMask((skgl__bool)(v[0] != 0)); break;
    case SKGL__S_COLOR_MASK:
        gl->ColorMask((skgl__bool)(v[0] != 0), (skgl__bool)(v[1] != 0), (skgl__bool)(v[2] != 0),
                      (skgl__bool)(v[3] != 0));
        break;
    case SKGL__S_POLY_OFFSET: memcpy(f, v, sizeof f); gl->PolygonOffset(f[0], f[1]); break;
    case SKGL__S_POLYGON_MODE: gl->PolygonMode(SKGL__FRONT_AND_BACK, (skgl__enum)v[0]); break;
    case SKGL__S_BLEND_EQ: gl->BlendEquationSeparate((skgl__enum)v[0], (skgl__enum)v[1]); break;
    case SKGL__S_BLEND_FUNC:
        gl->BlendFuncSeparate((skgl__enum)v[0], (skgl__enum)v[1], (skgl__enum)v[2], (skgl__enum)v[3]);
        break;
    case SKGL__S_PROGRAM: gl->UseProgram((skgl__uint)v[0]); break;
    case SKGL__S_VAO: gl->BindVertexArray((skgl__uint)v[0]); break;
    case SKGL__S_PACK_BUFFER: gl->BindBuffer(SKGL__PIXEL_PACK_BUFFER, (skgl__uint)v[0]); break;
    case SKGL__S_UNPACK_BUFFER: gl->BindBuffer(SKGL__PIXEL_UNPACK_BUFFER, (skgl__uint)v[0]); break;
    case SKGL__S_ACTIVE: gl->ActiveTexture((skgl__enum)v[0]); break;
    default: break;
    }
}

static void skgl__st_begin(const skgl_context *ctx, skgl__st *st)
{
    st->restore = !ctx->caller_owns;
    memset(st->flags, 0, sizeof st->flags);
}

static void skgl__st_set(skgl_context *ctx, skgl__st *st, int item, const skgl__int *v);

/* the unit an item belongs to active (texture bindings are per active unit) */
static void skgl__st_unit(skgl_context *ctx, skgl__st *st, int item)
{
    if (item >= SKGL__S_UNIT0) {
        skgl__int a = SKGL__TEXTURE0 + ((item - SKGL__S_UNIT0) >> 2);
        skgl__st_set(ctx, st, SKGL__S_ACTIVE, &a);
    }
}

/* state this API lacks: OpenGL ES has no polygon mode, takes every point's
   size from gl_PointSize and samples cube maps seamlessly always; depth
   clamp is GL_EXT_depth_clamp's. Never read, set or put back there. */
static int skgl__st_absent(const skgl_context *ctx, int item)
{
    if (ctx->caps.api != SKGL_API_GLES3) return 0;
    return item == SKGL__S_POLYGON_MODE || item == SKGL__S_POINT_SIZE || item == SKGL__S_SEAMLESS ||
           (item == SKGL__S_DEPTH_CLAMP && !ctx->caps.depth_clamp);
}

/* reads the caller's value the first time (default mode); afterwards the
   tracked one. A sampler binding is read with its unit active, but set
   without (glBindSampler names the unit). */
static void skgl__st_save(skgl_context *ctx, skgl__st *st, int item)
{
    if (!st->restore || (st->flags[item] & SKGL__S_SAVED) || skgl__st_absent(ctx, item)) return;
    skgl__st_unit(ctx, st, item);
    skgl__st_query(&ctx->gl, item, st->orig[item]);
    memcpy(st->cur[item], st->orig[item], sizeof st->cur[item]);
    st->flags[item] |= SKGL__S_SAVED | SKGL__S_KNOWN;
}

static void skgl__st_set(skgl_context *ctx, skgl__st *st, int item, const skgl__int *v)
{
    int n = skgl__st_n(item);
    if (skgl__st_absent(ctx, item)) return;
    skgl__st_save(ctx, st, item);
    if ((st->flags[item] & SKGL__S_KNOWN) && memcmp(st->cur[item], v, sizeof(skgl__int) * (size_t)n) == 0) return;
    if (item >= SKGL__S_UNIT0 && ((item - SKGL__S_UNIT0) & 3) != SKGL__T_SAMPLER) skgl__st_unit(ctx, st, item);
    skgl__st_apply(&ctx->gl, item, v);
    memcpy(st->cur[item], v, sizeof(skgl__int) * (size_t)n);
    st->flags[item] |= SKGL__S_KNOWN;
}

static void skgl__st_set1(skgl_context *ctx, skgl__st *st, int item, skgl__int v)
{
    skgl__int a[4];
    a[0] = v; a[1] = a[2] = a[3] = 0;
    skgl__st_set(ctx, st, item, a);
}
static void skgl__st_set4(skgl_context *ctx, skgl__st *st, int item, skgl__int a, skgl__int b, skgl__int c,
                          skgl__int d)
{
    skgl__int v[4];
    v[0] = a; v[1] = b; v[2] = c; v[3] = d;
    skgl__st_set(ctx, st, item, v);
}
static void skgl__st_offset(skgl_context *ctx, skgl__st *st, float factor, float units)
{
    skgl__int v[4] = {0, 0, 0, 0};
    float f[2];
    f[0] = factor; f[1] = units;
    memcpy(v, f, sizeof f);
    skgl__st_set(ctx, st, SKGL__S_POLY_OFFSET, v);
}
/* a texture on a unit, with the sampler object (0: the texture's own parameters) */
static void skgl__st_texture(skgl_context *ctx, skgl__st *st, int unit, int target, skgl__uint tex,
                             skgl__uint sampler)
{
    skgl__st_set1(ctx, st, SKGL__S_TEX(unit, target), (skgl__int)tex);
    skgl__st_set1(ctx, st, SKGL__S_TEX(unit, SKGL__T_SAMPLER), (skgl__int)sampler);
}
/* Textures on several units, in an order that saves unit switches: the
   default mode starts on the unit the caller has active (read once, as
   the restore needs it anyway), so that neither the binds nor the restore
   switch to it; caller-owns mode binds unit 0 last and leaves it active. */
typedef struct skgl__unitbind {
    int unit, target;
    skgl__uint tex, sampler;
} skgl__unitbind;
static void skgl__st_units(skgl_context *ctx, skgl__st *st, const skgl__unitbind *b, int n)
{
    int i, pass, first = -1;
    if (st->restore) {
        skgl__st_save(ctx, st, SKGL__S_ACTIVE);
        first = st->cur[SKGL__S_ACTIVE][0] - SKGL__TEXTURE0;
    }
    for (pass = 0; pass < 3; pass++)   /* the active unit, then the others but 0, then 0 */
        for (i = 0; i < n; i++) {
            int u = b[i].unit;
            if (pass == 0 ? u == first : u != first && (pass == 1 ? u != 0 : u == 0))
                skgl__st_texture(ctx, st, u, b[i].target, b[i].tex, b[i].sampler);
        }
}

/* both framebuffer targets (a read-back reads GL_READ_FRAMEBUFFER):
   glBindFramebuffer(GL_FRAMEBUFFER) sets both in one call when neither is
   there yet */
static void skgl__st_framebuffer(skgl_context *ctx, skgl__st *st, skgl__uint fb)
{
    skgl__st_save(ctx, st, SKGL__S_DRAW_FB);
    skgl__st_save(ctx, st, SKGL__S_READ_FB);
    if ((st->flags[SKGL__S_DRAW_FB] & SKGL__S_KNOWN) && st->cur[SKGL__S_DRAW_FB][0] == (skgl__int)fb) {
        skgl__st_set1(ctx, st, SKGL__S_READ_FB, (skgl__int)fb);
        return;
    }
    if ((st->flags[SKGL__S_READ_FB] & SKGL__S_KNOWN) && st->cur[SKGL__S_READ_FB][0] == (skgl__int)fb) {
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)fb);
        return;
    }
    ctx->gl.BindFramebuffer(SKGL__FRAMEBUFFER, fb);
    st->cur[SKGL__S_DRAW_FB][0] = st->cur[SKGL__S_READ_FB][0] = (skgl__int)fb;
    st->flags[SKGL__S_DRAW_FB] |= SKGL__S_KNOWN;
    st->flags[SKGL__S_READ_FB] |= SKGL__S_KNOWN;
}
/* what the caller's draw callback may have changed is no longer known
   (it is still put back from the saved value) */
static void skgl__st_forget(skgl__st *st, int item) { st->flags[item] &= (unsigned char)~SKGL__S_KNOWN; }

/* 1: the item must be put back */
static int skgl__st_dirty(const skgl__st *st, int item)
{
    if (!(st->flags[item] & SKGL__S_SAVED)) return 0;
    if (!(st->flags[item] & SKGL__S_KNOWN)) return 1;
    return memcmp(st->cur[item], st->orig[item], sizeof(skgl__int) * (size_t)skgl__st_n(item)) != 0;
}

static void skgl__st_end(skgl_context *ctx, skgl__st *st)
{
    const skgl__api *gl = &ctx->gl;
    int i, k, u, first, last, order[SKGL__UNITS], n = 0;
    if (!st->restore) {
        /* caller-owns mode: framebuffer 0 (draw and read, where shadowkit
           bound one) and no pixel buffer, so that nothing the caller does
           next writes into shadowkit's objects; the rest stays as set */
        int d = (st->flags[SKGL__S_DRAW_FB] & SKGL__S_KNOWN) && st->cur[SKGL__S_DRAW_FB][0] != 0;
        int r = (st->flags[SKGL__S_READ_FB] & SKGL__S_KNOWN) && st->cur[SKGL__S_READ_FB][0] != 0;
        if (d && r) skgl__st_framebuffer(ctx, st, 0);
        else if (d) skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, 0);
        else if (r) skgl__st_set1(ctx, st, SKGL__S_READ_FB, 0);
        if ((st->flags[SKGL__S_PACK_BUFFER] & SKGL__S_KNOWN) && st->cur[SKGL__S_PACK_BUFFER][0] != 0)
            skgl__st_set1(ctx, st, SKGL__S_PACK_BUFFER, 0);
        if ((st->flags[SKGL__S_UNPACK_BUFFER] & SKGL__S_KNOWN) && st->cur[SKGL__S_UNPACK_BUFFER][0] != 0)
            skgl__st_set1(ctx, st, SKGL__S_UNPACK_BUFFER, 0);
        return;
    }
    /* framebuffers: one call for both when the caller had one for both */
    if (skgl__st_dirty(st, SKGL__S_DRAW_FB) && skgl__st_dirty(st, SKGL__S_READ_FB) &&
        st->orig[SKGL__S_DRAW_FB][0] == st->orig[SKGL__S_READ_FB][0]) {
        gl->BindFramebuffer(SKGL__FRAMEBUFFER, (skgl__uint)st->orig[SKGL__S_DRAW_FB][0]);
    } else {
        if (skgl__st_dirty(st, SKGL__S_DRAW_FB)) skgl__st_apply(gl, SKGL__S_DRAW_FB, st->orig[SKGL__S_DRAW_FB]);
        if (skgl__st_dirty(st, SKGL__S_READ_FB)) skgl__st_apply(gl, SKGL__S_READ_FB, st->orig[SKGL__S_READ_FB]);
    }
    for (i = SKGL__S_VIEWPORT; i < SKGL__S_ACTIVE; i++) {
        if (!skgl__st_dirty(st, i)) continue;
        if (i == SKGL__S_PROGRAM) {
            /* the caller's program may have been deleted while current: it
               lived on only as long as it stayed current, and binding its
               name now would be GL_INVALID_VALUE (Dear ImGui's issue #6220).
               Program 0 then, as GL would have left it. */
            skgl__uint p = (skgl__uint)st->orig[i][0];
            gl->UseProgram(p == 0 || gl->IsProgram(p) ? p : 0);
            continue;
        }
        skgl__st_apply(gl, i, st->orig[i]);
    }
    /* texture units: first the one active now, the caller's active one last */
    first = (st->flags[SKGL__S_ACTIVE] & SKGL__S_KNOWN) ? st->cur[SKGL__S_ACTIVE][0] - SKGL__TEXTURE0 : -1;
    last = (st->flags[SKGL__S_ACTIVE] & SKGL__S_SAVED) ? st->orig[SKGL__S_ACTIVE][0] - SKGL__TEXTURE0 : -1;
    if (first >= 0 && first < SKGL__UNITS) order[n++] = first;
    for (u = 0; u < SKGL__UNITS; u++)
        if (u != first && u != last) order[n++] = u;
    if (last >= 0 && last < SKGL__UNITS && last != first) order[n++] = last;
    for (i = 0; i < n; i++) {
        int any = 0;
        u = order[i];
        for (k = 0; k < 4; k++) any |= skgl__st_dirty(st, SKGL__S_TEX(u, k));
        if (!any) continue;
        for (k = 0; k < 4; k++) {
            int item = SKGL__S_TEX(u, k);
            if (!skgl__st_dirty(st, item)) continue;
            if (k != SKGL__T_SAMPLER) skgl__st_unit(ctx, st, item);
            skgl__st_apply(gl, item, st->orig[item]);
        }
    }
    if (skgl__st_dirty(st, SKGL__S_ACTIVE)) skgl__st_apply(gl, SKGL__S_ACTIVE, st->orig[SKGL__S_ACTIVE]);
}

/* the state of every depth pass: both faces (open meshes cast from both
   sides), LESS with writes, slope-scaled bias, filled polygons. Blending
   and the colour mask do not matter: the framebuffer has no colour buffer.
   The passes clear with glClearBufferfv(GL_DEPTH, 0, 1.0), which leaves
   GL_DEPTH_CLEAR_VALUE alone (glClear would need it set and put back) but
   still obeys the depth write mask and the scissor test, both set here. */
static void skgl__clear_depth(skgl_context *ctx)
{
    static const float one = 1.0f;
    ctx->gl.ClearBufferfv(SKGL__DEPTH, 0, &one);
}

static void skgl__st_depth_pass(skgl_context *ctx, skgl__st *st, float slope_bias, float depth_bias)
{
    skgl__st_set1(ctx, st, SKGL__S_CULL_FACE, 0);
    skgl__st_set1(ctx, st, SKGL__S_DEPTH_TEST, 1);
    skgl__st_set1(ctx, st, SKGL__S_DEPTH_FUNC, SKGL__LESS);
    skgl__st_set1(ctx, st, SKGL__S_DEPTH_MASK, 1);
    /* a host left in wireframe (glPolygonMode GL_LINE) must not get
       wireframe shadow maps */
    skgl__st_set1(ctx, st, SKGL__S_POLYGON_MODE, SKGL__FILL);
    if (slope_bias > 0.0f || depth_bias > 0.0f) {
        skgl__st_set1(ctx, st, SKGL__S_POLY_FILL, 1);
        skgl__st_offset(ctx, st, slope_bias > 0.0f ? slope_bias : 0.0f, depth_bias > 0.0f ? depth_bias : 0.0f);
    } else skgl__st_set1(ctx, st, SKGL__S_POLY_FILL, 0);
}

/* the state of a full-screen pass into colour targets (no depth buffer:
   the depth test, its mask and polygon offset do not apply) */
static void skgl__st_screen_pass(skgl_context *ctx, skgl__st *st)
{
    skgl__st_set1(ctx, st, SKGL__S_BLEND, 0);
    skgl__st_set1(ctx, st, SKGL__S_CULL_FACE, 0);
    skgl__st_set4(ctx, st, SKGL__S_COLOR_MASK, 1, 1, 1, 1);
    skgl__st_set1(ctx, st, SKGL__S_POLYGON_MODE, SKGL__FILL);
    skgl__st_set1(ctx, st, SKGL__S_VAO, (skgl__int)ctx->empty_vao);
}

/* pixel transfers between client memory and GL without padding or offsets
   (pack: read-backs; unpack: uploads), no pixel buffer bound unless given */
#if !defined(SKGL_NO_FERKO) || !defined(SKGL_NO_RMSM) || !defined(SKGL_NO_CACHE) || !defined(SKGL_NO_SOFT)
static void skgl__st_pack(skgl_context *ctx, skgl__st *st, skgl__uint buffer, int rows, int row_bytes)
{
    skgl__st_set1(ctx, st, SKGL__S_PACK_BUFFER, (skgl__int)buffer);
    if (rows > 1) {
        /* a read of one row has no row stride: alignment and row length do
           not apply to it, only the skips; rows whose length is a multiple
           of 8 bytes are aligned under every GL_PACK_ALIGNMENT (1, 2, 4, 8) */
        if (row_bytes % 8 != 0) skgl__st_set1(ctx, st, SKGL__S_PACK_ALIGNMENT, 1);
        skgl__st_set1(ctx, st, SKGL__S_PACK_ROW_LENGTH, 0);
    }
    skgl__st_set1(ctx, st, SKGL__S_PACK_SKIP_PIXELS, 0);
    skgl__st_set1(ctx, st, SKGL__S_PACK_SKIP_ROWS, 0);
}
#endif
static void skgl__st_unpack(skgl_context *ctx, skgl__st *st)
{
    skgl__st_set1(ctx, st, SKGL__S_UNPACK_BUFFER, 0);
    skgl__st_set1(ctx, st, SKGL__S_UNPACK_ALIGNMENT, 1);
    skgl__st_set1(ctx, st, SKGL__S_UNPACK_ROW_LENGTH, 0);
    skgl__st_set1(ctx, st, SKGL__S_UNPACK_SKIP_PIXELS, 0);
    skgl__st_set1(ctx, st, SKGL__S_UNPACK_SKIP_ROWS, 0);
}


/* ---- 4. The context ----------------------------------------------------- */
// >>context
/* 4.1 the log, the arguments, programs and samplers */
// >>log
/* The error log (skgl_error_log) holds the last failure of the
   current call: every public call that takes the context clears it first,
   so an old message never stands for a new error. A broken rule is one
   message naming the argument or field, its value and the rule:
   "skgl_shadow_create: desc.lambda = 1.5: in (0, 1]". */
static void skgl__log_clear(skgl_context *ctx)
{
    if (ctx) { ctx->log[0] = 0; ctx->failed = 0; }
}

/* the message just written into the log, to desc.logger */
static void skgl__log_emit(skgl_context *ctx, skgl_log_level level)
{
    if (ctx->logger.func && !ctx->log_quiet && ctx->log[0]) ctx->logger.func(ctx->logger.user, level, ctx->log);
}

/* formats the message into the log (and to the logger); returns r */
static sk_result skgl__fail(skgl_context *ctx, sk_result r, const char *fmt, ...)
{
    va_list ap;
    char msg[sizeof ctx->log];
    if (!ctx) return r;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);   /* the arguments may quote the log itself */
    va_end(ap);
    memcpy(ctx->log, msg, sizeof msg);
    ctx->failed = 1;
    skgl__log_emit(ctx, SKGL_LOG_ERROR);
    return r;
}

/* every error return has a message: one that came back from deep inside a
   call without its own gets the call's name and the result */
static sk_result skgl__said(skgl_context *ctx, const char *fn, sk_result r, const char *hint)
{
    if (r == SK_OK || ctx->failed) return r;
    return skgl__fail(ctx, r, "%s: %s%s%s", fn, sk_result_string(r), hint ? ": " : "", hint ? hint : "");
}

/* GL's error codes by name (glGetError) */
static const char *skgl__gl_error_name(skgl__enum e)
{
    switch (e) {
    case 0x0500: return "GL_INVALID_ENUM";
    case 0x0501: return "GL_INVALID_VALUE";
    case 0x0502: return "GL_INVALID_OPERATION";
    case 0x0503: return "GL_STACK_OVERFLOW";
    case 0x0504: return "GL_STACK_UNDERFLOW";
    case 0x0505: return "GL_OUT_OF_MEMORY";
    case 0x0506: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case 0x0507: return "GL_CONTEXT_LOST";
    default: return "an unknown GL error";
    }
}

/* GL errors the application left pending are not shadowkit's: cleared
   (glGetError returns and clears one flag per call; a context may hold one
   per kind), named in the log as a warning and to the logger; the call
   goes on. Create calls do it always, so that their own check at the end
   sees only their own errors; the per-frame calls with desc.debug. */
static void skgl__pending_errors(skgl_context *ctx, const char *fn)
{
    skgl__enum e = ctx->gl.GetError(), first = e;
    int n = 0;
    while (e != 0 && ++n < 8) e = ctx->gl.GetError();
    if (first == 0) return;
    snprintf(ctx->log, sizeof ctx->log,
             "GL error pending before %s: %s%s (left by the application, cleared; not shadowkit's)", fn,
             skgl__gl_error_name(first), n > 1 ? " and more" : "");
    skgl__log_emit(ctx, SKGL_LOG_WARNING);
}

/* a create call's own GL error (the application's were cleared on entry):
   SK_ERR_GL naming it and what was being made; SK_OK without one */
static sk_result skgl__create_check(skgl_context *ctx, const char *fn, const char *what)
{
    skgl__enum e = ctx->gl.GetError();
    int n = 0;
    if (e == 0) return SK_OK;
    while (ctx->gl.GetError() != 0 && ++n < 8) {}
    return skgl__fail(ctx, SK_ERR_GL, "%s: %s while making %s", fn, skgl__gl_error_name(e), what);
}

/* what every public call that takes the context does first: the log
   cleared, and with desc.debug (create calls: always) the application's
   pending GL errors taken out of the way */
static void skgl__enter(skgl_context *ctx, const char *fn, int always_drain)
{
    skgl__log_clear(ctx);
    ctx->stage = NULL;
    ctx->call = fn;
    if (ctx->debug || always_drain) skgl__pending_errors(ctx, fn);
}

/* a render (or another call that draws) from inside a draw callback would
   rebind the outer pass's program and reset its model location: refused */
static sk_result skgl__not_nested(skgl_context *ctx, const char *fn)
{
    if (ctx->model_loc < 0) return SK_OK;
    return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                      "%s: called inside a draw callback of another pass (render every light before or after "
                      "the others' passes, never from their callbacks)",
                      fn);
}

/* What every create (light, atlas, caster) does first and last.
   skgl__create_open: the context required (without one there is no log),
   the call entered (the application's pending GL errors cleared), the
   desc (no_desc) and out (no_out) required, and not from inside a draw
   callback. skgl__create_alloc: the object, zeroed, or NULL with
   SK_ERR_CAPACITY in the log. skgl__create_close: the call's own GL error
   (what: what it was making), and any failure named for the call in the
   log; on a failure the caller gives back what it made (its destroy, or
   its free before the object is listed) and returns this result. */
static sk_result skgl__create_open(skgl_context *ctx, const char *fn, int no_desc, int no_out)
{
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, fn, 1);
    if (no_desc || no_out)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: %s is NULL", fn, no_desc ? "desc" : "out");
    return skgl__not_nested(ctx, fn);
}

static void *skgl__create_alloc(skgl_context *ctx, const char *fn, size_t bytes)
{
    void *o = SKGL_MALLOC(bytes);
    if (o) memset(o, 0, bytes);
    else (void)skgl__fail(ctx, SK_ERR_CAPACITY, "%s: out of memory (%lu bytes)", fn, (unsigned long)bytes);
    return o;
}

static sk_result skgl__create_close(skgl_context *ctx, const char *fn, sk_result r, const char *what)
{
    if (r == SK_OK) r = skgl__create_check(ctx, fn, what);
    return skgl__said(ctx, fn, r, NULL);
}

/* one rule of a desc: when cond fails, the message names the field and its
   value, and the caller returns SK_ERR_INVALID_ARG (needs ctx in scope) */
#define SKGL__RULE(cond, fn, field, value, rule)                                                   \
    do {                                                                                           \
        if (!(cond))                                                                               \
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.%s = %g: %s", fn, field,          \
                              (double)(value), rule);                                              \
    } while (0)

/* the polygon offset rules of every light's depth passes */
static sk_result skgl__offset_rules(skgl_context *ctx, const char *fn, float slope_bias, float depth_bias)
{
    SKGL__RULE(slope_bias >= 0.0f && slope_bias <= 1e4f, fn, "slope_bias", slope_bias,
               "in [0, 10000] (disable_polygon_offset for none)");
    SKGL__RULE(depth_bias >= 0.0f && depth_bias <= 1e6f, fn, "depth_bias", depth_bias,
               "in [0, 1000000] (disable_polygon_offset for none)");
    return SK_OK;
}

/* the bias and filtering rules directional and point lights share */
static sk_result skgl__bias_rules(skgl_context *ctx, const char *fn, float slope_bias, float depth_bias,
                                  float normal_bias, skgl_bias bias, float plane_bias, int pcf_radius)
{
    sk_result r = skgl__offset_rules(ctx, fn, slope_bias, depth_bias);
    if (r != SK_OK) return r;
    SKGL__RULE(normal_bias >= 0.0f && normal_bias <= 64.0f, fn, "normal_bias", normal_bias, "in [0, 64] texels");
    SKGL__RULE((int)bias >= (int)SKGL_BIAS_RECEIVER_PLANE && (int)bias <= (int)SKGL_BIAS_NONE, fn, "bias", bias,
               "one of skgl_bias");
    SKGL__RULE(plane_bias >= 0.0f && plane_bias <= 64.0f, fn, "plane_bias", plane_bias,
               "in [0, 64] texels (disable_plane_bias for none)");
    SKGL__RULE(pcf_radius >= 0 && pcf_radius <= 8, fn, "pcf_radius", pcf_radius,
               "in 1..8 (disable_pcf_kernel for one 2x2 compare)");
    return SK_OK;
}

// >>needs
/* what a technique needs of the context (skgl_caps): SK_ERR_GL at
   create, the message naming the feature and the extension that gives it */
#define SKGL__NEED(have, fn, what, feature)                                                        \
    do {                                                                                           \
        if (!(have))                                                                               \
            return skgl__fail(ctx, SK_ERR_GL, "%s: %s needs %s, which this context lacks", fn, what, \
                              feature);                                                            \
    } while (0)
#define SKGL__FLOAT_RENDER "float colour targets (GL_EXT_color_buffer_float on OpenGL ES and WebGL2)"
#define SKGL__FLOAT_BLEND "blending into float targets (GL_EXT_float_blend on OpenGL ES and WebGL2)"
#define SKGL__GEOMETRY "geometry shaders (OpenGL 3.2, OpenGL ES 3.2)"

// >>args
/* a call's arguments: each check names the argument and its value */
#define SKGL__TRY(call)                                                                            \
    do {                                                                                           \
        sk_result skgl__r_ = (call);                                                               \
        if (skgl__r_ != SK_OK) return skgl__r_;                                                    \
    } while (0)

static sk_result skgl__arg_ptr(skgl_context *ctx, const char *fn, const void *p, const char *name)
{
    return p ? SK_OK : skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: %s is NULL", fn, name);
}

static sk_result skgl__arg_name(skgl_context *ctx, const char *fn, unsigned name, const char *what)
{
    return name ? SK_OK : skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: %s = 0: a GL name is required", fn, what);
}

/* a snippet prefix: NULL, "", or a GLSL identifier of at most
   SKGL_PREFIX_MAX characters not reserved by GLSL (gl_, a double
   underscore); 0 when it is one */
static int skgl__prefix_bad(const char *prefix)
{
    size_t i, n;
    if (!prefix || !prefix[0]) return 0;
    n = strlen(prefix);
    if (n > SKGL_PREFIX_MAX || !isalpha((unsigned char)prefix[0]) || strncmp(prefix, "gl_", 3) == 0) return 1;
    for (i = 0; i < n; i++)
        if (!(isalnum((unsigned char)prefix[i]) || prefix[i] == '_') || (prefix[i] == '_' && prefix[i + 1] == '_'))
            return 1;
    return 0;
}

static sk_result skgl__arg_prefix(skgl_context *ctx, const char *fn, const char *prefix)
{
    if (!skgl__prefix_bad(prefix)) return SK_OK;
    return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                      "%s: prefix = \"%.40s\": a GLSL identifier of 1 to %d characters, a letter first, not "
                      "gl_ and no double underscore",
                      fn, prefix, SKGL_PREFIX_MAX);
}

/* src with every identifier that starts with sk_ starting with prefix
   instead, and every SK_ with prefix in capitals (the snippet's names and
   its #defines); into out (cap bytes, NUL-terminated, cut short if it does
   not fit); returns the whole length, or -1 for a bad prefix */
static int skgl__glsl_prefixed(const char *src, const char *prefix, char *out, int cap)
{
    size_t n = 0, k, plen;
    const char *c;
    if (skgl__prefix_bad(prefix) || !prefix || !prefix[0] || cap < 0) return -1;
    plen = strlen(prefix);
#define SKGL__PUT(ch) do { if (out && n + 1 < (size_t)cap) out[n] = (ch); n++; } while (0)
    for (c = src; *c; c++) {
        int start = c == src || !(isalnum((unsigned char)c[-1]) || c[-1] == '_');
        if (start && (strncmp(c, "sk_", 3) == 0 || strncmp(c, "SK_", 3) == 0)) {
            int upper = c[0] == 'S';
            for (k = 0; k < plen; k++) SKGL__PUT(upper ? (char)toupper((unsigned char)prefix[k]) : prefix[k]);
            c += 2;
            continue;
        }
        SKGL__PUT(*c);
    }
#undef SKGL__PUT
    if (out && cap > 0) out[n < (size_t)cap ? n : (size_t)cap - 1] = 0;
    return (int)n;
}

/* a camera with finite matrices whose view-projection inverts (into *inv) */
static sk_result skgl__arg_camera(skgl_context *ctx, const char *fn, const skgl_camera *cam, sk_mat4 *inv)
{
    sk_mat4 unused;
    SKGL__TRY(skgl__arg_ptr(ctx, fn, cam, "cam"));
    if (!sk__mat_finite(&cam->view))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->view has a NaN or an infinity", fn);
    if (!sk__mat_finite(&cam->proj))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj has a NaN or an infinity", fn);
    if (!sk_mat4_inverse(sk_mat4_mul(cam->proj, cam->view), inv ? inv : &unused))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj * cam->view is singular", fn);
    return SK_OK;
}

/* With desc.clip_zero_to_one, shadowkit's own depth passes run under
   OpenGL's clip depth (its light matrices are OpenGL's): back = 0 around
   them, then back = 1 gives the caller's zero-to-one back. */
static void skgl__clip_depth(skgl_context *ctx, int back)
{
    if (ctx->clip_zero_to_one) ctx->ClipControl(SKGL__LOWER_LEFT, back ? SKGL__ZERO_TO_ONE : SKGL__NEGATIVE_ONE_TO_ONE);
}

// >>camera
/* The camera's depth convention (CAMERA CONVENTIONS). Every
   call that takes a camera works on the same camera in OpenGL's
   convention (near at NDC z -1, a finite far at +1: what the fits and
   shadowkit's own passes assume) and reads the caller's depth buffer
   through u_depth_map: NDC z = d * x + y (2, -1 under OpenGL's clip
   depth; 1, 0 with glClipControl's zero-to-one), z the near plane's depth
   (1 with reverse-Z: background is 0), w a depth on every pixel's ray
   (the far plane's, or 0.5 when it is at infinity). */
static const float skgl__dmap_gl[4] = {2.0f, -1.0f, 0.0f, 1.0f};

typedef struct skgl__cam {
    skgl_camera gl;                        /* the camera in OpenGL's convention */
    float dmap[4];                         /* u_depth_map for the caller's depth buffer */
} skgl__cam;

/* a mask or analysis program's u_depth_map (program current): OpenGL's
   convention set now, as sent[] remembers; returns its location */
static skgl__int skgl__depth_map_init(const skgl__api *gl, skgl__uint prog, float sent[4])
{
    skgl__int loc = gl->GetUniformLocation(prog, "u_depth_map");
    if (loc >= 0) gl->Uniform4fv(loc, 1, skgl__dmap_gl);
    memcpy(sent, skgl__dmap_gl, sizeof skgl__dmap_gl);
    return loc;
}

/* u_depth_map when it differs from what the program holds (program current) */
static void skgl__depth_map_send(const skgl__api *gl, skgl__int loc, float sent[4], const float dmap[4])
{
    if (memcmp(sent, dmap, sizeof(float) * 4) == 0) return;
    memcpy(sent, dmap, sizeof(float) * 4);
    if (loc >= 0) gl->Uniform4fv(loc, 1, dmap);
}

/* near n and far f (+INF: an infinite perspective) of proj under the clip
   convention zo, and whether depth is reversed (the near plane at the
   larger NDC z); 0 when proj is neither a perspective (NDC z = -a + b /
   distance, a = m[10], b = m[14]) nor an orthographic (NDC z = b - a
   distance) projection of positive near and larger far */
static int skgl__cam_planes(const sk_mat4 *proj, int zo, double *n, double *f, int *reversed)
{
    const float *m = proj->m;
    double a = m[10], b = m[14], lo = zo ? 0.0 : -1.0, vn, vf;
    if (m[11] == -1.0f && m[15] == 0.0f && m[3] == 0.0f && m[7] == 0.0f) {
        if (b == 0.0) return 0;
        *reversed = b > 0.0;
        vn = *reversed ? 1.0 : lo;
        vf = *reversed ? lo : 1.0;
        if (vn + a == 0.0) return 0;
        *n = b / (vn + a);
        *f = vf + a == 0.0 ? (double)SK__INF : b / (vf + a);
        return *n > 0.0 && sk__finite((float)*n) && (*f == (double)SK__INF || (*f > *n && sk__finite((float)*f)));
    }
    if (m[11] == 0.0f && m[15] == 1.0f && m[3] == 0.0f && m[7] == 0.0f && a != 0.0) {
        *reversed = a > 0.0;
        vn = *reversed ? 1.0 : lo;
        vf = *reversed ? lo : 1.0;
        *n = (b - vn) / a;
        *f = (b - vf) / a;
        return sk__finite((float)*n) && sk__finite((float)*f) && *f > *n;
    }
    return 0;
}

/* the camera checked (skgl__arg_camera), and in OpenGL's
   convention; an infinite far plane ends at the farthest corner of bounds
   (a little beyond; at least twice the near plane), or at 100000 near
   planes without bounds. OpenGL's own convention with a finite far plane
   comes back unchanged, bit for bit. */
static sk_result skgl__camera_in(skgl_context *ctx, const char *fn, const skgl_camera *cam, const sk_aabb *bounds,
                                 skgl__cam *out)
{
    double n = 0.0, f = 0.0;
    int reversed = 0, ortho, i;
    float *m;
    int zo = ctx->clip_zero_to_one;
    SKGL__TRY(skgl__arg_camera(ctx, fn, cam, NULL));
    out->gl = *cam;
    memcpy(out->dmap, skgl__dmap_gl, sizeof skgl__dmap_gl);
    if (!skgl__cam_planes(&cam->proj, zo, &n, &f, &reversed)) {
        if (!zo) return SK_OK;   /* read as it is (a technique that needs near/far says so) */
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "%s: cam->proj is neither a perspective nor an orthographic projection with "
                          "0 < near < far under desc.clip_zero_to_one",
                          fn);
    }
    out->dmap[0] = zo ? 1.0f : 2.0f;
    out->dmap[1] = zo ? 0.0f : -1.0f;
    out->dmap[2] = reversed ? 1.0f : 0.0f;
    out->dmap[3] = f == (double)SK__INF ? 0.5f : reversed ? 0.0f : 1.0f;
    if (!zo && !reversed && f != (double)SK__INF) return SK_OK;
    ortho = cam->proj.m[11] == 0.0f;
    if (f == (double)SK__INF) {
        f = 2.0 * n;
        if (bounds && sk__aabb_valid(bounds)) {
            for (i = 0; i < 8; i++) {
                double z = -(double)sk__xform_affine(&cam->view, sk__aabb_corner(bounds, i)).z * 1.01;
                if (z > f) f = z;
            }
        } else f = 1e5 * n;
    }
    m = out->gl.proj.m;
    m[2] = m[6] = 0.0f;
    m[10] = (float)(ortho ? -2.0 / (f - n) : -(f + n) / (f - n));
    m[14] = (float)(ortho ? -(f + n) / (f - n) : -2.0 * f * n / (f - n));
    return SK_OK;
}

/* a scene with a draw callback (when one is needed) and valid bounds */
/* 1 when skgl_dynamic.bounds is given (not all 0) */
static int skgl__has_dynamic_bounds(const sk_aabb *b)
{
    return b->min.x != 0.0f || b->min.y != 0.0f || b->min.z != 0.0f || b->max.x != 0.0f || b->max.y != 0.0f ||
           b->max.z != 0.0f;
}

SKGLDEF sk_result skgl_set_dynamic(skgl_context *ctx, const skgl_dynamic *dyn)
{
    const char *fn = "skgl_set_dynamic";
    const sk_aabb *b;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_set_dynamic", 0);
    if (!dyn) { memset(&ctx->dyn, 0, sizeof ctx->dyn); return SK_OK; }
    b = &dyn->bounds;
    if (!dyn->draw) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: dyn->draw is NULL (NULL dyn: no dynamic casters)", fn);
    if (skgl__has_dynamic_bounds(b) && !sk__aabb_valid(b))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "%s: dyn->bounds = (%g %g %g)..(%g %g %g): not finite, or min above max", fn,
                          (double)b->min.x, (double)b->min.y, (double)b->min.z, (double)b->max.x, (double)b->max.y,
                          (double)b->max.z);
    ctx->dyn = *dyn;
    return SK_OK;
}

/* The scene's bounds fit the maps (SCENE ACCESS): a box of some size
   (zero bounds, a point, would clip every map to nothing and end the
   shadows where they begin), min below max, every coordinate within
   SKGL__WORLD_MAX (squared distances then stay finite in float) */
#define SKGL__WORLD_MAX 1e18f
static sk_result skgl__arg_scene(skgl_context *ctx, const char *fn, const skgl_scene *scene, int needs_draw)
{
    const sk_aabb *b;
    const char *why = NULL;
    SKGL__TRY(skgl__arg_ptr(ctx, fn, scene, "scene"));
    if (needs_draw && !scene->draw) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: scene->draw is NULL", fn);
    b = &scene->bounds;
    if (!sk__aabb_valid(b)) why = "not finite, or min above max";
    else if (!(SK_FABS(b->min.x) <= SKGL__WORLD_MAX && SK_FABS(b->min.y) <= SKGL__WORLD_MAX &&
               SK_FABS(b->min.z) <= SKGL__WORLD_MAX && SK_FABS(b->max.x) <= SKGL__WORLD_MAX &&
               SK_FABS(b->max.y) <= SKGL__WORLD_MAX && SK_FABS(b->max.z) <= SKGL__WORLD_MAX))
        why = "a coordinate beyond 1e18";
    else if (b->max.x - b->min.x <= 0.0f && b->max.y - b->min.y <= 0.0f && b->max.z - b->min.z <= 0.0f)
        why = "an empty box (all casters and receivers must be inside: the bounds clip the maps and end the "
              "shadows)";
    if (why)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: scene->bounds = (%g %g %g)..(%g %g %g): %s", fn,
                          (double)b->min.x, (double)b->min.y, (double)b->min.z, (double)b->max.x, (double)b->max.y,
                          (double)b->max.z, why);
    return SK_OK;
}

/* a finite vector; nonzero = 1: of some length (a direction) */
static sk_result skgl__arg_vec(skgl_context *ctx, const char *fn, sk_vec3 v, const char *name, int nonzero)
{
    if (!sk__v3_finite(v) || (nonzero && sk__len(v) == 0.0f))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: %s = (%g %g %g): %s", fn, name, (double)v.x, (double)v.y,
                          (double)v.z, nonzero ? "finite and nonzero" : "finite");
    return SK_OK;
}

/* a texture unit the call may use: 0..last */
static sk_result skgl__arg_unit(skgl_context *ctx, const char *fn, int unit, int last)
{
    if (unit < 0 || unit > last)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: unit = %d: in 0..%d", fn, unit, last);
    return SK_OK;
}

static void skgl__set_log(skgl_context *ctx, const char *what, const char *detail)
{
    size_t n = strlen(what);
    if (detail == ctx->log || what == ctx->log) {   /* quoting the log itself */
        char keep[sizeof ctx->log];
        memcpy(keep, ctx->log, sizeof keep);
        skgl__set_log(ctx, what == ctx->log ? keep : what, detail == ctx->log ? keep : detail);
        return;
    }
    if (n >= sizeof ctx->log) n = sizeof ctx->log - 1;
    memcpy(ctx->log, what, n);
    ctx->log[n] = 0;
    if (detail && n + 2 < sizeof ctx->log) {
        size_t m = strlen(detail);
        ctx->log[n] = ':'; ctx->log[n + 1] = ' ';
        if (m > sizeof ctx->log - n - 3) m = sizeof ctx->log - n - 3;
        memcpy(ctx->log + n + 2, detail, m);
        ctx->log[n + 2 + m] = 0;
    }
    ctx->failed = 1;
    skgl__log_emit(ctx, SKGL_LOG_ERROR);
}

/* n sources (at most 11) after the dialect's #version (and precision) compiled into a shader
   of the given type; 0 on failure, the driver's message in log */
static skgl__uint skgl__shader_n(skgl_context *ctx, skgl__enum type, const char *const *src, int n, char *log,
                                 int log_size)
{
    const char *all[12];
    skgl__uint sh = ctx->gl.CreateShader(type);
    skgl__int ok = 0;
    int i;
    all[0] = ctx->glsl_version;
    for (i = 0; i < n && i < 11; i++) all[i + 1] = src[i];
    ctx->gl.ShaderSource(sh, i + 1, all, NULL);
    ctx->gl.CompileShader(sh);
    ctx->gl.GetShaderiv(sh, SKGL__COMPILE_STATUS, &ok);
    if (ok) return sh;
    log[0] = 0;
    ctx->gl.GetShaderInfoLog(sh, (skgl__sizei)log_size, NULL, log);
    ctx->gl.DeleteShader(sh);
    return 0;
}

static skgl__uint skgl__shader(skgl_context *ctx, skgl__enum type, const char *a, const char *b)
{
    const char *src[2];
    char log[900];
    skgl__uint sh;
    src[0] = a; src[1] = b ? b : "";
    sh = skgl__shader_n(ctx, type, src, 2, log, (int)sizeof log);
    if (!sh) skgl__set_log(ctx, "shader compile failed", log);
    return sh;
}

/* Links n compiled shaders into a program and deletes the shaders. A 0
   among them (its compile failed) deletes the others and returns 0. */
static skgl__uint skgl__link(skgl_context *ctx, const skgl__uint *sh, int n)
{
    skgl__uint p = 0;
    skgl__int ok = 0;
    int i, complete = 1;
    for (i = 0; i < n; i++) complete &= sh[i] != 0;
    if (complete) {
        p = ctx->gl.CreateProgram();
        for (i = 0; i < n; i++) ctx->gl.AttachShader(p, sh[i]);
        ctx->gl.LinkProgram(p);
    }
    for (i = 0; i < n; i++)
        if (sh[i]) ctx->gl.DeleteShader(sh[i]);
    if (!complete) return 0;
    ctx->gl.GetProgramiv(p, SKGL__LINK_STATUS, &ok);
    if (!ok) {
        char log[900];
        log[0] = 0;
        ctx->gl.GetProgramInfoLog(p, (skgl__sizei)sizeof log, NULL, log);
        skgl__set_log(ctx, "program link failed", log);
        ctx->gl.DeleteProgram(p);
        return 0;
    }
    ctx->objects++;
    return p;
}

/* vertex + fragment (fs_a then fs_b); compiling stops at the first failure */
static skgl__uint skgl__program(skgl_context *ctx, const char *vs, const char *fs_a, const char *fs_b)
{
    skgl__uint sh[2];
    sh[0] = skgl__shader(ctx, SKGL__VERTEX_SHADER, vs, NULL);
    sh[1] = sh[0] ? skgl__shader(ctx, SKGL__FRAGMENT_SHADER, fs_a, fs_b) : 0;
    return skgl__link(ctx, sh, 2);
}

/* the directional mask: the snippet (with its EVSM part when evsm: then
   sk_filter picks it per light), then shadow_mask.frag */
static skgl__uint skgl__mask_program(skgl_context *ctx, int evsm)
{
    const char *fs[3];
    char log[900];
    skgl__uint sh[2];
    fs[0] = evsm ? "#define SK_SHADOW_EVSM 1\n" : "";
    fs[1] = skgl__glsl(SKGL__GLSL_SHADOW_SAMPLE_GLSL);
    fs[2] = skgl__glsl(SKGL__GLSL_SHADOW_MASK_FRAG);
    sh[0] = skgl__shader(ctx, SKGL__VERTEX_SHADER, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT), NULL);
    sh[1] = sh[0] ? skgl__shader_n(ctx, SKGL__FRAGMENT_SHADER, fs, 3, log, (int)sizeof log) : 0;
    if (sh[0] && !sh[1]) skgl__set_log(ctx, "shader compile failed", log);
    return skgl__link(ctx, sh, 2);
}

static skgl__uint skgl__sampler(skgl_context *ctx, int compare)
{
    skgl__uint s = 0;
    ctx->gl.GenSamplers(1, &s);
    ctx->objects++;
    ctx->gl.SamplerParameteri(s, SKGL__TEXTURE_MIN_FILTER, compare ? SKGL__LINEAR : SKGL__NEAREST);
    ctx->gl.SamplerParameteri(s, SKGL__TEXTURE_MAG_FILTER, compare ? SKGL__LINEAR : SKGL__NEAREST);
    ctx->gl.SamplerParameteri(s, SKGL__TEXTURE_WRAP_S, SKGL__CLAMP_TO_EDGE);
    ctx->gl.SamplerParameteri(s, SKGL__TEXTURE_WRAP_T, SKGL__CLAMP_TO_EDGE);
    ctx->gl.SamplerParameteri(s, SKGL__TEXTURE_COMPARE_MODE, compare ? SKGL__COMPARE_REF_TO_TEXTURE : SKGL__NONE);
    ctx->gl.SamplerParameteri(s, SKGL__TEXTURE_COMPARE_FUNC, SKGL__LEQUAL);
    return s;
}

/* 4.2 uniforms */
/* a location of -1 (the name is not in the program, or the compiler
   dropped it) takes no call */
static void skgl__u1i(const skgl__api *gl, skgl__int loc, skgl__int v) { if (loc >= 0) gl->Uniform1i(loc, v); }
static void skgl__u1f(const skgl__api *gl, skgl__int loc, float v) { if (loc >= 0) gl->Uniform1f(loc, v); }

/* Locations of the GLSL snippets' uniforms (skgl_glsl_snippet,
   skgl_point_glsl_snippet), per program: shadowkit's own mask programs
   hold one each, and the context caches those of the user's programs
   (SKGL__PROG_CACHE of them, the least recently bound replaced first) on
   their first skgl_*_bind. A program's uniforms keep their values until it
   is linked again, so each entry also remembers whose constants (sampler
   units, filter, bias) the program holds and the values of the uniforms
   that seldom change: neither is sent again while it is still there. */
enum {
    SKGL__L_MAP, SKGL__L_TABLE, SKGL__L_RMSM, SKGL__L_PAGES0, SKGL__L_LEVELS, SKGL__L_MIN_LEVEL, SKGL__L_PAGE,
    SKGL__L_LIGHT_VP, SKGL__L_SPLITS, SKGL__L_LAYERS, SKGL__L_SELECT_BY_MAP, SKGL__L_MAP_EXTENT,
    SKGL__L_SELECT_EXTENT, SKGL__L_BLEND_BAND, SKGL__L_NORMAL_BIAS, SKGL__L_BIAS_MODE, SKGL__L_PLANE_BIAS,
    SKGL__L_PCF, SKGL__L_LIGHT_DIR, SKGL__L_FILTER_WORLD, SKGL__L_SHADOW_N
};
static const char *const skgl__shadow_names[SKGL__L_SHADOW_N] = {
    "sk_shadow_map", "sk_page_table", "sk_rmsm", "sk_rmsm_pages0", "sk_rmsm_levels", "sk_rmsm_min_level",
    "sk_rmsm_page", "sk_light_vp", "sk_splits", "sk_layers", "sk_select_by_map", "sk_map_extent",
    "sk_select_extent", "sk_blend_band", "sk_normal_bias", "sk_bias_mode", "sk_plane_bias", "sk_pcf_radius",
    "sk_light_dir", "sk_filter_world"};
/* EVSM's (SK_SHADOW_EVSM), after the others in a program's locations */
enum { SKGL__L_MOMENTS = SKGL__L_SHADOW_N, SKGL__L_FILTER, SKGL__L_EVSM, SKGL__L_SHADOW_ALL };
static const char *const skgl__evsm_names[SKGL__L_SHADOW_ALL - SKGL__L_SHADOW_N] = {"sk_moments", "sk_filter",
                                                                                     "sk_evsm"};
/* every directional location fits a program entry (a compile error otherwise) */
typedef char skgl__locs_fit[SKGL__L_SHADOW_ALL <= SKGL__LOCS ? 1 : -1];
enum {
    SKGL__P_CUBE, SKGL__P_ATLAS, SKGL__P_INDIRECTION, SKGL__P_POS, SKGL__P_RANGE, SKGL__P_DEPTH, SKGL__P_TEXEL,
    SKGL__P_NORMAL_BIAS, SKGL__P_PCF, SKGL__P_BIAS_MODE, SKGL__P_PLANE_BIAS, SKGL__P_FACES, SKGL__P_SPOT,
    SKGL__P_BASIS, SKGL__P_COS, SKGL__L_POINT_N
};
static const char *const skgl__point_names[SKGL__L_POINT_N] = {
    "sk_point_cube", "sk_point_atlas", "sk_point_indirection", "sk_point_pos", "sk_point_range", "sk_point_depth",
    "sk_point_texel", "sk_point_normal_bias", "sk_point_pcf", "sk_point_bias_mode", "sk_point_plane_bias",
    "sk_point_faces", "sk_point_spot", "sk_point_basis", "sk_point_cos"};

static void skgl__progent_lookup(skgl_context *ctx, skgl__progent *e, skgl__uint program, int kind,
                                 const char *prefix)
{
    int i, n = kind == SKGL__PK_SHADOW ? (int)SKGL__L_SHADOW_N : (int)SKGL__L_POINT_N;
    const char *const *names = kind == SKGL__PK_SHADOW ? skgl__shadow_names : skgl__point_names;
    char name[SKGL_PREFIX_MAX + 32];
    memset(e, 0, sizeof *e);
    e->program = program;
    e->kind = kind;
    strcpy(e->prefix, prefix);
    for (i = 0; i < SKGL__LOCS; i++) e->loc[i] = -1;
    for (i = 0; i < n; i++) {
        /* "sk_x" is "<prefix>x" in a prefixed snippet (skgl__glsl_prefixed) */
        if (prefix[0]) snprintf(name, sizeof name, "%s%s", prefix, names[i] + 3);
        e->loc[i] = ctx->gl.GetUniformLocation(program, prefix[0] ? name : names[i]);
    }
    for (i = 0; kind == SKGL__PK_SHADOW && i < SKGL__L_SHADOW_ALL - SKGL__L_SHADOW_N; i++) {
        if (prefix[0]) snprintf(name, sizeof name, "%s%s", prefix, skgl__evsm_names[i] + 3);
        e->loc[SKGL__L_SHADOW_N + i] = ctx->gl.GetUniformLocation(program, prefix[0] ? name : skgl__evsm_names[i]);
    }
    ctx->gl.GetProgramiv(program, SKGL__ACTIVE_UNIFORMS, &e->uniforms);
}

/* Is the program under this name still the one whose locations were
   cached? A program linked again, or deleted and made anew under the same
   name (GL hands freed names out again), has its uniforms back at 0 and
   maybe other locations. Default mode, one bind = two reads: the active
   uniform count (a different program has, in practice, another one), then
   the constant the last bind set that can never be 0 (sk_rmsm_page,
   sk_point_range), read at its cached location (valid when the count
   matched). desc.debug: every location looked up again, then that constant.
   Caller-owns mode (no debug) reads nothing and trusts the cache: call
   skgl_forget_program. */
static int skgl__progent_changed(skgl_context *ctx, const skgl__progent *e)
{
    skgl__int n = -1;
    int i;
    if (ctx->debug) {
        skgl__progent fresh;
        skgl__progent_lookup(ctx, &fresh, e->program, e->kind, e->prefix);
        for (i = 0; i < SKGL__LOCS; i++)
            if (fresh.loc[i] != e->loc[i]) return 1;
    } else if (ctx->caller_owns) {
        return 0;
    } else {
        ctx->gl.GetProgramiv(e->program, SKGL__ACTIVE_UNIFORMS, &n);
        if (n != e->uniforms) return 1;
    }
    if (e->owner != 0 && e->kind == SKGL__PK_SHADOW && e->loc[SKGL__L_PAGE] >= 0) {
        skgl__int v = 0;
        ctx->gl.GetUniformiv(e->program, e->loc[SKGL__L_PAGE], &v);
        return v != e->sentinel_i;
    }
    if (e->owner != 0 && e->kind == SKGL__PK_POINT && e->loc[SKGL__P_RANGE] >= 0) {
        float v = 0.0f;
        ctx->gl.GetUniformfv(e->program, e->loc[SKGL__P_RANGE], &v);
        return v != e->sentinel_f;
    }
    return 0;
}

/* the cache entry of a user program, looked up anew on a miss or when the
   program changed under its name */
static skgl__progent *skgl__user_program(skgl_context *ctx, skgl__uint program, int kind, const char *prefix)
{
    skgl__progent *e, *victim = &ctx->progs[0];
    int i;
    ctx->tick++;
    for (i = 0; i < SKGL__PROG_CACHE; i++) {
        e = &ctx->progs[i];
        if (e->program == program && e->kind == kind && strcmp(e->prefix, prefix) == 0) {
            if (skgl__progent_changed(ctx, e)) skgl__progent_lookup(ctx, e, program, kind, prefix);
            e->tick = ctx->tick;
            return e;
        }
        if (e->tick < victim->tick) victim = e;
    }
    skgl__progent_lookup(ctx, victim, program, kind, prefix);
    victim->tick = ctx->tick;
    return victim;
}

/* desc.debug: a program that is one (glIsProgram) and is current, as the
   binds ask (a bind sets uniforms on the current program) */
static sk_result skgl__arg_program(skgl_context *ctx, const char *fn, skgl__uint program)
{
    skgl__int cur = 0;
    if (!ctx->debug) return SK_OK;
    if (!ctx->gl.IsProgram(program))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: program = %u: not a linked GL program", fn, program);
    ctx->gl.GetIntegerv(SKGL__CURRENT_PROGRAM, &cur);
    if ((skgl__uint)cur != program)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: program = %u is not current (glUseProgram it first; %d is)",
                          fn, program, (int)cur);
    return SK_OK;
}

/* desc.debug: the program holds the snippet under this prefix (its map
   sampler, `map`, is an active uniform). Without it the bind would put the
   map's texture on a unit that another sampler of the program, of another
   type, may read: the draw raises GL_INVALID_OPERATION. */
static sk_result skgl__snippet_present(skgl_context *ctx, const char *fn, const skgl__progent *e, int map_loc,
                                       skgl__uint program, const char *prefix, const char *map)
{
    if (!ctx->debug || e->loc[map_loc] >= 0) return SK_OK;
    return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                      "%s: program = %u has no active uniform %s%s under prefix \"%s\": the snippet is missing, "
                      "was pasted under another prefix, or its shadow function is never called",
                      fn, program, prefix && prefix[0] ? prefix : "sk_", map + 3, prefix ? prefix : "");
}

SKGLDEF void skgl_forget_program(skgl_context *ctx, unsigned program)
{
    int i;
    if (!ctx) return;
    skgl__log_clear(ctx);
    if (!program) return;
    for (i = 0; i < SKGL__PROG_CACHE; i++)
        if (ctx->progs[i].program == program) memset(&ctx->progs[i], 0, sizeof ctx->progs[i]);
}

/* 4.3 the user's textures: sizes and framebuffer checks, by name */
/* The mask texture's size (the viewport of the mask pass) and the depth
   texture's (the analysis' targets) are asked of GL once per texture name
   (glGetTexLevelParameteriv) and remembered here; whether a mask texture is
   colour-renderable is checked once per name too. A texture given storage
   of another size or format under the same name needs skgl_forget_texture. */
static skgl__texent *skgl__texture(skgl_context *ctx, skgl__uint tex)
{
    skgl__texent *e, *victim = &ctx->texs[0];
    int i;
    ctx->tick++;
    for (i = 0; i < SKGL__TEX_CACHE; i++) {
        e = &ctx->texs[i];
        if (e->tex == tex) { e->tick = ctx->tick; return e; }
        if (e->tick < victim->tick) victim = e;
    }
    memset(victim, 0, sizeof *victim);
    victim->tex = tex;
    victim->tick = ctx->tick;
    return victim;
}

SKGLDEF void skgl_forget_texture(skgl_context *ctx, unsigned texture)
{
    int i;
    if (!ctx) return;
    skgl__log_clear(ctx);
    if (!texture) return;
    for (i = 0; i < SKGL__TEX_CACHE; i++)
        if (ctx->texs[i].tex == texture) memset(&ctx->texs[i], 0, sizeof ctx->texs[i]);
    if (ctx->mask_fbo_tex == texture) {
        /* GL detaches a deleted texture only from the framebuffer bound at
           the time: the masks' framebuffer would keep it alive */
        skgl__st st;
        skgl__st_begin(ctx, &st);
        skgl__st_set1(ctx, &st, SKGL__S_DRAW_FB, (skgl__int)ctx->mask_fbo);
        ctx->gl.FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT0, SKGL__TEXTURE_2D, 0, 0);
        ctx->mask_fbo_tex = 0;
        skgl__st_end(ctx, &st);
    }
}

SKGLDEF sk_result skgl_remember_texture(skgl_context *ctx, unsigned texture, int width, int height)
{
    static const char fn[] = "skgl_remember_texture";
    skgl__texent *e;
    int most;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, fn, 0);
    most = ctx->caps.max_texture_size > 0 ? ctx->caps.max_texture_size : 65536;
    SKGL__TRY(skgl__arg_name(ctx, fn, texture, "texture"));
    if (width < 1 || height < 1 || width > most || height > most)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: width x height = %d x %d: each in 1..%d (GL_MAX_TEXTURE_SIZE)",
                          fn, width, height, most);
    if (!ctx->gl.IsTexture(texture))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: texture = %u: not a texture (never made, never bound, or "
                          "deleted)", fn, texture);
    skgl_forget_texture(ctx, texture);
    e = skgl__texture(ctx, texture);
    e->w = width;
    e->h = height;
    return SK_OK;
}

/* The size of a texture the caller made: level 0's, as GL had it the
   first time (bound on unit 1's GL_TEXTURE_2D to ask), or as
   skgl_remember_texture gave it. NULL, or what is wrong: no level 0; with
   desc.debug, which asks every time, a size that changed under the same
   name; without glGetTexLevelParameteriv, a size never given. */
static const char *skgl__texture_size(skgl_context *ctx, skgl__st *st, skgl__uint tex, int *w, int *h)
{
    skgl__texent *e = skgl__texture(ctx, tex);
    /* a name glGenTextures never gave, deleted, or never bound: binding it
       would raise GL_INVALID_OPERATION (asked once per name) */
    if (!e->named) {
        if (!ctx->gl.IsTexture(tex)) return "not a texture (never made, never bound, or deleted)";
        e->named = 1;
    }
    if (!ctx->caps.texture_size) {
        if (e->w <= 0 || e->h <= 0)
            return "this GL cannot be asked a texture's size (OpenGL ES 3.0, WebGL2): give it with "
                   "skgl_remember_texture";
    } else if (e->w <= 0 || e->h <= 0 || ctx->debug) {
        skgl__int tw = 0, th = 0;
        skgl__st_set1(ctx, st, SKGL__S_TEX(1, SKGL__T_2D), (skgl__int)tex);
        skgl__st_unit(ctx, st, SKGL__S_TEX(1, SKGL__T_2D));
        ctx->gl.GetTexLevelParameteriv(SKGL__TEXTURE_2D, 0, SKGL__TEXTURE_WIDTH, &tw);
        ctx->gl.GetTexLevelParameteriv(SKGL__TEXTURE_2D, 0, SKGL__TEXTURE_HEIGHT, &th);
        if (tw <= 0 || th <= 0 || tw > 65536 || th > 65536)
            return "the texture has no level 0 (no storage, or not a GL_TEXTURE_2D)";
        if (e->w > 0 && (e->w != tw || e->h != th))
            return "the texture's size changed since it was remembered: call skgl_forget_texture after giving "
                   "a texture new storage";
        e->w = tw;
        e->h = th;
    }
    *w = e->w;
    *h = e->h;
    return NULL;
}

/* a texture the call reads (a camera depth or normal texture; 0 passes:
   the caller checks what is required): a texture, with storage where GL can
   be asked its size; once per name (desc.debug: every call) */
static sk_result skgl__arg_texture(skgl_context *ctx, skgl__st *st, const char *fn, skgl__uint tex, const char *what)
{
    skgl__texent *e;
    const char *why = NULL;
    int w = 0, h = 0;
    if (!tex) return SK_OK;
    e = skgl__texture(ctx, tex);
    if (e->named && e->w > 0 && !ctx->debug) return SK_OK;
    if (ctx->caps.texture_size) why = skgl__texture_size(ctx, st, tex, &w, &h);
    else if (!e->named) {
        if (!ctx->gl.IsTexture(tex)) why = "not a texture (never made, never bound, or deleted)";
        else e->named = 1;
    }
    if (why) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: %s = %u: %s", fn, what, tex, why);
    return SK_OK;
}

/* 4.4 GPU timers: a ring of queries read late -------------------------
   With desc.timing, each timed pass of a light takes the next of
   SKGL__TIMER_RING GL_TIME_ELAPSED queries. Before it, the query about to
   be reused (three passes ago) is read if GL_QUERY_RESULT_AVAILABLE says
   it is done, and if it is not, this pass goes untimed rather than wait;
   then the one of two passes ago, likewise. The stats report the latest
   result read: two frames old (three when the GPU is behind), -1 before
   the first. */
static void skgl__timer_free(skgl_context *ctx, skgl__timer *t)
{
    int i;
    for (i = 0; i < SKGL__TIMER_RING; i++)
        if (t->q[i]) { ctx->gl.DeleteQueries(1, &t->q[i]); ctx->objects--; t->q[i] = 0; }
}
static void skgl__timer_init(skgl_context *ctx, skgl__timer *t)
{
    int i;
    memset(t, 0, sizeof *t);
    t->ms = -1.0f;
    if (!ctx->timing) return;
    for (i = 0; i < SKGL__TIMER_RING; i++) { ctx->gl.GenQueries(1, &t->q[i]); ctx->objects++; }
}
/* OpenGL ES's timer queries (GL_EXT_disjoint_timer_query): a disjoint
   event (a clock change, a context switch on the GPU) since the last ask
   makes the results read now unreliable; asking clears the flag. Desktop
   GL has no such flag (no call made there). */
static int skgl__timer_disjoint(skgl_context *ctx)
{
    skgl__int disjoint = 0;
    if (ctx->caps.api != SKGL_API_GLES3) return 0;
    ctx->gl.GetIntegerv(SKGL__GPU_DISJOINT, &disjoint);
    return disjoint != 0;
}

/* 1 when slot i's result was there and has been read */
static int skgl__timer_read(skgl_context *ctx, skgl__timer *t, int i)
{
    skgl__uint avail = 0;
    skgl__u64 ns = 0;
    if (!t->pending[i]) return 1;
    ctx->gl.GetQueryObjectuiv(t->q[i], SKGL__QUERY_RESULT_AVAILABLE, &avail);
    if (!avail) return 0;
    ctx->gl.GetQueryObjectui64v(t->q[i], SKGL__QUERY_RESULT, &ns);
    t->pending[i] = 0;
    if (!skgl__timer_disjoint(ctx)) t->ms = (float)((double)ns * 1e-6);
    return 1;
}
static void skgl__timer_begin(skgl_context *ctx, skgl__timer *t)
{
    int slot;
    t->running = 0;
    if (!ctx->timing || !t->q[0]) return;
    slot = (int)(t->frame % SKGL__TIMER_RING);
    /* the slot to reuse (three passes ago; usually read already), then two
       passes ago: the newer result read last, and queries end in order, so
       a busy older one means the newer is busy too */
    if (!skgl__timer_read(ctx, t, slot)) return;                                 /* still busy: untimed */
    (void)skgl__timer_read(ctx, t, (int)((t->frame + 1) % SKGL__TIMER_RING));
    ctx->gl.BeginQuery(SKGL__TIME_ELAPSED, t->q[slot]);
    t->running = 1;
}
static void skgl__timer_end(skgl_context *ctx, skgl__timer *t)
{
    if (!t->running) return;
    /* measuring mode: a renderer that bins draws and rasterises them later
       on its own threads (Mesa's llvmpipe) would otherwise end the query
       before the work is done and time almost nothing; glFinish inside the
       query holds it open until the pass has run */
    if (ctx->timing == SKGL_TIMING_SYNC) ctx->gl.Finish();
    ctx->gl.EndQuery(SKGL__TIME_ELAPSED);
    t->pending[t->frame % SKGL__TIMER_RING] = 1;
    if (ctx->timing == SKGL_TIMING_SYNC) {
        /* measuring mode: this pass's own time, waited for (a stall) */
        skgl__u64 ns = 0;
        ctx->gl.GetQueryObjectui64v(t->q[t->frame % SKGL__TIMER_RING], SKGL__QUERY_RESULT, &ns);
        t->pending[t->frame % SKGL__TIMER_RING] = 0;
        if (!skgl__timer_disjoint(ctx)) t->ms = (float)((double)ns * 1e-6);
    }
    t->frame++;
    t->running = 0;
}

/* 4.5 read-backs a frame late: a ring of pixel buffers with fences ------
   A read-back that must not stall goes into the next free one of
   SKGL__RING pixel pack buffers (glReadPixels into a buffer returns at
   once), followed by a fence. Later calls poll the fences, oldest first,
   with a zero timeout (glClientWaitSync never waits then) and read the
   newest buffer whose fence has signalled; fences signal in order, so the
   first unsignalled one ends the poll. When every buffer is still in
   flight, the new read-back is skipped (the GPU is three frames behind;
   nothing is waited for). The poll flushes (GL_SYNC_FLUSH_COMMANDS_BIT): a
   fence never flushed to the GPU may never signal. */
#if !defined(SKGL_NO_FERKO) || !defined(SKGL_NO_RMSM) || !defined(SKGL_NO_SOFT)   /* the rings' users */
/* the bound pixel pack buffer's first `bytes` into out: glGetBufferSubData
   (GL, WebGL2), else mapped for reading (OpenGL ES 3.0 has no
   glGetBufferSubData). 0 when the map failed (out untouched). */
static int skgl__pack_buffer_read(skgl_context *ctx, size_t bytes, void *out)
{
    void *map;
    if (ctx->caps.buffer_read) {
        ctx->gl.GetBufferSubData(SKGL__PIXEL_PACK_BUFFER, 0, (ptrdiff_t)bytes, out);
        return 1;
    }
    map = ctx->gl.MapBufferRange(SKGL__PIXEL_PACK_BUFFER, 0, (ptrdiff_t)bytes, SKGL__MAP_READ_BIT);
    if (!map) return 0;
    memcpy(out, map, bytes);
    ctx->gl.UnmapBuffer(SKGL__PIXEL_PACK_BUFFER);
    return 1;
}

static void skgl__ring_free(skgl_context *ctx, skgl__ring *r)
{
    int i;
    for (i = 0; i < SKGL__RING; i++) {
        if (r->sync[i]) { ctx->gl.DeleteSync(r->sync[i]); ctx->objects--; r->sync[i] = NULL; }
        if (r->buf[i]) { ctx->gl.DeleteBuffers(1, &r->buf[i]); ctx->objects--; r->buf[i] = 0; }
    }
}
static void skgl__ring_create(skgl_context *ctx, skgl__st *st, skgl__ring *r, size_t bytes)
{
    int i;
    r->bytes = bytes;
    for (i = 0; i < SKGL__RING; i++) {
        ctx->gl.GenBuffers(1, &r->buf[i]);
        ctx->objects++;
        skgl__st_set1(ctx, st, SKGL__S_PACK_BUFFER, (skgl__int)r->buf[i]);
        ctx->gl.BufferData(SKGL__PIXEL_PACK_BUFFER, (ptrdiff_t)bytes, NULL, SKGL__STREAM_READ);
    }
}
/* the newest signalled read-back into out (r->bytes), its slot; -1: none
   has landed since the last call */
static int skgl__ring_poll(skgl_context *ctx, skgl__st *st, skgl__ring *r, void *out)
{
    int k, newest = -1;
    for (k = 0; k < SKGL__RING; k++) {
        int i = (r->next + k) % SKGL__RING;   /* oldest first */
        skgl__enum w;
        if (!r->sync[i]) continue;
        w = ctx->gl.ClientWaitSync(r->sync[i], SKGL__SYNC_FLUSH_COMMANDS_BIT, 0);
        if (w != SKGL__ALREADY_SIGNALED && w != SKGL__CONDITION_SATISFIED) break;
        ctx->gl.DeleteSync(r->sync[i]);
        ctx->objects--;
        r->sync[i] = NULL;
        newest = i;
    }
    if (newest < 0) return -1;
    skgl__st_set1(ctx, st, SKGL__S_PACK_BUFFER, (skgl__int)r->buf[newest]);
    if (!skgl__pack_buffer_read(ctx, r->bytes, out)) return -1;
    return newest;
}
/* the slot the next read-back goes to, bound as the pack buffer; -1 when
   every buffer is in flight */
static int skgl__ring_slot(skgl_context *ctx, skgl__st *st, skgl__ring *r)
{
    int i = r->next;
    if (r->sync[i]) return -1;
    skgl__st_set1(ctx, st, SKGL__S_PACK_BUFFER, (skgl__int)r->buf[i]);
    return i;
}
/* after the read-back into slot i: its fence */
static void skgl__ring_fence(skgl_context *ctx, skgl__ring *r, int i)
{
    r->sync[i] = ctx->gl.FenceSync(SKGL__SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (r->sync[i]) ctx->objects++;
    r->next = (i + 1) % SKGL__RING;
}
#endif


/* 4.6 the context's lifetime */
static void skgl__release(skgl_context *ctx)
{
    skgl__api *gl = &ctx->gl;
    skgl__uint *progs[12];
    int i;
    progs[0] = &ctx->depth_prog; progs[1] = &ctx->mask_prog; progs[2] = &ctx->ferko_prog;
    progs[3] = &ctx->reduce_prog; progs[4] = &ctx->final_prog; progs[5] = &ctx->rmsm_prog;
    progs[6] = &ctx->request_prog; progs[7] = &ctx->layered_prog; progs[8] = &ctx->evsm_prog[0];
    progs[9] = &ctx->evsm_prog[1]; progs[10] = &ctx->mask_evsm.prog; progs[11] = NULL;
    for (i = 0; progs[i]; i++)
        if (*progs[i]) { gl->DeleteProgram(*progs[i]); ctx->objects--; *progs[i] = 0; }
    if (ctx->empty_vao) { gl->DeleteVertexArrays(1, &ctx->empty_vao); ctx->objects--; }
    if (ctx->mask_fbo) { gl->DeleteFramebuffers(1, &ctx->mask_fbo); ctx->objects--; }
    if (ctx->cmp_sampler) { gl->DeleteSamplers(1, &ctx->cmp_sampler); ctx->objects--; }
    if (ctx->point_sampler) { gl->DeleteSamplers(1, &ctx->point_sampler); ctx->objects--; }
    ctx->empty_vao = ctx->mask_fbo = 0;
    ctx->cmp_sampler = ctx->point_sampler = 0;
}

/* the mask program's locations and constant uniforms (mask_prog, after a link) */
static void skgl__mask_locations(skgl_context *ctx, skgl__st *st)
{
    skgl__api *gl = &ctx->gl;
    skgl__progent_lookup(ctx, &ctx->mask_ent, ctx->mask_prog, SKGL__PK_SHADOW, "");
    ctx->mask_u_has_normals = gl->GetUniformLocation(ctx->mask_prog, "u_has_normals");
    ctx->mask_u_camera = gl->GetUniformLocation(ctx->mask_prog, "u_camera");
    ctx->mask_u_contact = gl->GetUniformLocation(ctx->mask_prog, "u_contact");
    ctx->mask_u_view_proj = gl->GetUniformLocation(ctx->mask_prog, "u_view_proj");
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->mask_prog);
    ctx->mask_u_depth_map = skgl__depth_map_init(gl, ctx->mask_prog, ctx->mask_dmap);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->mask_prog, "u_depth"), 1);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->mask_prog, "u_normals"), 2);
    ctx->mask_ent.has_normals = -1;
}

/* swaps the context's mask program (mask_* fields) with the EVSM one */
static void skgl__mask_swap(skgl_context *ctx)
{
    skgl__mask_prog *m = &ctx->mask_evsm, t;
    t.prog = ctx->mask_prog; ctx->mask_prog = m->prog; m->prog = t.prog;
    t.ent = ctx->mask_ent; ctx->mask_ent = m->ent; m->ent = t.ent;
    t.u_has_normals = ctx->mask_u_has_normals; ctx->mask_u_has_normals = m->u_has_normals;
    m->u_has_normals = t.u_has_normals;
    t.u_camera = ctx->mask_u_camera; ctx->mask_u_camera = m->u_camera; m->u_camera = t.u_camera;
    t.u_contact = ctx->mask_u_contact; ctx->mask_u_contact = m->u_contact; m->u_contact = t.u_contact;
    t.u_view_proj = ctx->mask_u_view_proj; ctx->mask_u_view_proj = m->u_view_proj; m->u_view_proj = t.u_view_proj;
    t.u_depth_map = ctx->mask_u_depth_map; ctx->mask_u_depth_map = m->u_depth_map; m->u_depth_map = t.u_depth_map;
    memcpy(t.contact, ctx->mask_contact, sizeof t.contact);
    memcpy(ctx->mask_contact, m->contact, sizeof t.contact);
    memcpy(m->contact, t.contact, sizeof t.contact);
    memcpy(t.dmap, ctx->mask_dmap, sizeof t.dmap);
    memcpy(ctx->mask_dmap, m->dmap, sizeof t.dmap);
    memcpy(m->dmap, t.dmap, sizeof t.dmap);
}

/* the constant uniforms of shadowkit's own programs (sampler units), set
   once after they are linked, and their locations */
static void skgl__own_programs(skgl_context *ctx, skgl__st *st)
{
    skgl__api *gl = &ctx->gl;
    ctx->depth_u_view_proj = gl->GetUniformLocation(ctx->depth_prog, "skgl_view_proj");
    ctx->depth_u_model = gl->GetUniformLocation(ctx->depth_prog, "skgl_model");
    ctx->model_loc = -1;   /* no caster pass under way */
    skgl__mask_locations(ctx, st);
}

/* the programs of a technique that did not build: SK_ERR_GL, the driver's
   message (in the log) quoted after what */
static sk_result skgl__programs_failed(skgl_context *ctx, const char *what)
{
    char driver[sizeof ctx->log];
    memcpy(driver, ctx->log, sizeof driver);
    return skgl__fail(ctx, SK_ERR_GL, "%s did not build on \"%.80s\": %.900s", what,
                      (const char *)ctx->gl.GetString(SKGL__VERSION), driver);
}

#ifndef SKGL_NO_FERKO
/* FERKO's analysis (the 4x4-block pass, the 16x16 MIN reduction, the last
   reduction into 2x1 texels): built with the first light that analyses
   (FERKO, AUTO, .fit_to_depth), then kept with the context and freed by
   skgl_destroy; those linked before one failed are kept for the next try */
static sk_result skgl__ferko_programs(skgl_context *ctx, skgl__st *st)
{
    skgl__api *gl = &ctx->gl;
    if (ctx->final_prog) return SK_OK;
    if (!ctx->ferko_prog)
        ctx->ferko_prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT),
                                        skgl__glsl(SKGL__GLSL_FERKO_ANALYZE_FRAG), NULL);
    if (ctx->ferko_prog && !ctx->reduce_prog)
        ctx->reduce_prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT), "#define SK_FERKO_FINAL 0\n",
                                         skgl__glsl(SKGL__GLSL_FERKO_REDUCE_FRAG));
    if (ctx->reduce_prog)
        ctx->final_prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT), "#define SK_FERKO_FINAL 1\n",
                                        skgl__glsl(SKGL__GLSL_FERKO_REDUCE_FRAG));
    if (!ctx->final_prog)
        return skgl__programs_failed(ctx, "skgl_shadow_create: the shaders of FERKO's analysis (desc.technique "
                                     "SKGL_FERKO or SKGL_AUTO, or desc.fit_to_depth)");
    ctx->ferko_u_ndc_to_light = gl->GetUniformLocation(ctx->ferko_prog, "u_ndc_to_light");
    ctx->ferko_u_world_w = gl->GetUniformLocation(ctx->ferko_prog, "u_world_w");
    ctx->ferko_u_view_z = gl->GetUniformLocation(ctx->ferko_prog, "u_view_z");
    ctx->ferko_u_depth_only = gl->GetUniformLocation(ctx->ferko_prog, "u_depth_only");
    ctx->ferko_depth_only = -1;
    ctx->ferko_view_z[0] = ctx->ferko_view_z[1] = ctx->ferko_view_z[2] = ctx->ferko_view_z[3] = 0.0f;   /* GL's own */
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->ferko_prog);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->ferko_prog, "u_depth"), 1);
    ctx->ferko_u_depth_map = skgl__depth_map_init(gl, ctx->ferko_prog, ctx->ferko_dmap);
    ctx->reduce_u_src_size = gl->GetUniformLocation(ctx->reduce_prog, "u_src_size");
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->reduce_prog);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->reduce_prog, "u_src"), 1);
    ctx->final_u_src_size = gl->GetUniformLocation(ctx->final_prog, "u_src_size");
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->final_prog);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->final_prog, "u_src"), 1);
    ctx->reduce_src[0] = ctx->final_src[0] = -1;
    return SK_OK;
}
#endif /* SKGL_NO_FERKO */

#ifndef SKGL_NO_RMSM
/* RMSM's per-pixel samples and page-request scatter: built with the first
   RMSM light, then kept with the context and freed by skgl_destroy */
static sk_result skgl__rmsm_programs(skgl_context *ctx, skgl__st *st)
{
    skgl__api *gl = &ctx->gl;
    if (ctx->request_prog) return SK_OK;
    if (!ctx->rmsm_prog)
        ctx->rmsm_prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT),
                                       skgl__glsl(SKGL__GLSL_RMSM_ANALYZE_FRAG), NULL);
    if (ctx->rmsm_prog)
        ctx->request_prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_RMSM_REQUEST_VERT),
                                          skgl__glsl(SKGL__GLSL_RMSM_REQUEST_FRAG), NULL);
    if (!ctx->request_prog)
        return skgl__programs_failed(ctx, "skgl_shadow_create: the shaders of RMSM's page analysis");
    ctx->rmsm_u_inv_view_proj = gl->GetUniformLocation(ctx->rmsm_prog, "u_inv_view_proj");
    ctx->rmsm_u_light = gl->GetUniformLocation(ctx->rmsm_prog, "u_light");
    ctx->rmsm_u_virtual_res = gl->GetUniformLocation(ctx->rmsm_prog, "u_virtual_res");
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->rmsm_prog);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->rmsm_prog, "u_depth"), 1);
    ctx->rmsm_u_depth_map = skgl__depth_map_init(gl, ctx->rmsm_prog, ctx->rmsm_dmap);
    ctx->rmsm_vres = -1.0f;
    ctx->request_u_pages0 = gl->GetUniformLocation(ctx->request_prog, "u_pages0");
    ctx->request_u_levels = gl->GetUniformLocation(ctx->request_prog, "u_levels");
    ctx->request_u_bands = gl->GetUniformLocation(ctx->request_prog, "u_bands");
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->request_prog);
    skgl__u1i(gl, gl->GetUniformLocation(ctx->request_prog, "u_samples"), 1);
    ctx->request_pages0 = ctx->request_levels = ctx->request_bands = -1;
    return SK_OK;
}
#endif

// >>caps
/* What the context offers (skgl_caps), from its version and
   extension strings, less desc->disable_caps; the optional entry points
   loaded where they exist. Fails below GL 3.3 and ES 3.0, and for an
   api the context does not speak. */
static int skgl__has_extension(skgl_context *ctx, const char *name)
{
    skgl__int n = 0, i;
    ctx->gl.GetIntegerv(SKGL__NUM_EXTENSIONS, &n);
    for (i = 0; i < n; i++) {
        const char *e = (const char *)ctx->gl.GetStringi(SKGL__EXTENSIONS, (skgl__uint)i);
        if (e && strcmp(e, name) == 0) return 1;
    }
    return 0;
}

static void *skgl__load_opt(const skgl_desc *desc, int wanted, const char *name)
{
    return wanted ? desc->getproc(name) : NULL;
}

static sk_result skgl__probe_caps(skgl_context *ctx, const skgl_desc *desc, int major, int minor)
{
    skgl_caps *c = &ctx->caps;
    const char *version = (const char *)ctx->gl.GetString(SKGL__VERSION);
    int es = version && strncmp(version, "OpenGL ES", 9) == 0, gl, off = (int)desc->disable_caps;
    void *p;
    static const char fn[] = "skgl_create";
    if (desc->api == SKGL_API_GL33 && es)
        return skgl__fail(ctx, SK_ERR_GL, "%s: desc.api = SKGL_API_GL33, but the context is \"%.200s\"", fn, version);
    if (desc->api == SKGL_API_GLES3 && !es)
        return skgl__fail(ctx, SK_ERR_GL, "%s: desc.api = SKGL_API_GLES3, but the context is \"%.200s\"", fn,
                          version ? version : "(no GL_VERSION)");
    if (es ? major < 3 : major < 3 || (major == 3 && minor < 3))
        return skgl__fail(ctx, SK_ERR_GL, "%s: the context is OpenGL%s %d.%d (\"%.200s\"): shadowkit needs %s", fn,
                          es ? " ES" : "", major, minor, version ? version : "(no GL_VERSION)",
                          es ? "OpenGL ES 3.0 or later" : "OpenGL 3.3 core or later");
    gl = !es;
    memset(c, 0, sizeof *c);
    c->api = es ? SKGL_API_GLES3 : SKGL_API_GL33;
    c->major = major;
    c->minor = minor;
    c->webgl = es && strstr(version, "WebGL") != NULL;
    c->geometry_shader = gl || major > 3 || minor >= 2;
    c->gpu_shader5 = gl ? major >= 4 || skgl__has_extension(ctx, "GL_ARB_gpu_shader5") : c->geometry_shader;
    c->float_render = gl || skgl__has_extension(ctx, "GL_EXT_color_buffer_float");
    c->float_blend = gl || skgl__has_extension(ctx, "GL_EXT_float_blend");
    c->norm16 = gl || skgl__has_extension(ctx, "GL_EXT_texture_norm16");
    c->depth_clamp = gl || skgl__has_extension(ctx, "GL_EXT_depth_clamp");
    c->timer_query = gl || skgl__has_extension(ctx, "GL_EXT_disjoint_timer_query") ||
                     skgl__has_extension(ctx, "GL_EXT_disjoint_timer_query_webgl2");
    c->texture_size = gl || (!c->webgl && (major > 3 || minor >= 1));
    c->buffer_read = gl || c->webgl;
    c->clip_control = gl ? major > 4 || (major == 4 && minor >= 5) || skgl__has_extension(ctx, "GL_ARB_clip_control")
                         : skgl__has_extension(ctx, "GL_EXT_clip_control");
    c->mip_render_level = !c->webgl;
    ctx->gl.GetIntegerv(SKGL__MAX_TEXTURE_SIZE, &c->max_texture_size);
    /* what the desc turns off */
    if (off & SKGL_CAP_GEOMETRY_SHADER) c->geometry_shader = 0;
    if ((off & SKGL_CAP_GPU_SHADER5) || !c->geometry_shader) c->gpu_shader5 = 0;
    if (off & SKGL_CAP_FLOAT_RENDER) c->float_render = 0;
    if ((off & SKGL_CAP_FLOAT_BLEND) || !c->float_render) c->float_blend = 0;
    if (off & SKGL_CAP_NORM16) c->norm16 = 0;
    if (off & SKGL_CAP_DEPTH_CLAMP) c->depth_clamp = 0;
    if (off & SKGL_CAP_TIMER_QUERY) c->timer_query = 0;
    if (off & SKGL_CAP_TEXTURE_SIZE) c->texture_size = 0;
    if (off & SKGL_CAP_BUFFER_READ) c->buffer_read = 0;
    if (off & SKGL_CAP_CLIP_CONTROL) c->clip_control = 0;
    if (off & SKGL_CAP_MIP_RENDER_LEVEL) c->mip_render_level = 0;
    /* the entry points behind them (void* -> function pointer through memcpy) */
#define SKGL__OPT(field, wanted, name) \
    p = skgl__load_opt(desc, wanted, name); memcpy(&ctx->gl.field, &p, sizeof p); \
    if ((wanted) && !p) return skgl__fail(ctx, SK_ERR_GL, "%s: desc.getproc(\"%s\") returned NULL: the context " \
                                          "offers it (%s), shadowkit needs it", fn, name, version ? version : "");
    SKGL__OPT(FramebufferTexture, c->geometry_shader, es ? "glFramebufferTextureEXT" : "glFramebufferTexture")
    SKGL__OPT(GetBufferSubData, c->buffer_read, "glGetBufferSubData")
    SKGL__OPT(MapBufferRange, !c->buffer_read, "glMapBufferRange")
    SKGL__OPT(UnmapBuffer, !c->buffer_read, "glUnmapBuffer")
    SKGL__OPT(GetTexLevelParameteriv, c->texture_size, "glGetTexLevelParameteriv")
    SKGL__OPT(GetQueryObjectui64v, c->timer_query, es ? "glGetQueryObjectui64vEXT" : "glGetQueryObjectui64v")
    SKGL__OPT(PolygonMode, gl, "glPolygonMode")
#undef SKGL__OPT
    ctx->glsl_version = gl ? "#version 330 core\n"
                        : c->geometry_shader ? "#version 320 es\n" SKGL__ES_PRECISION
                                             : "#version 300 es\n" SKGL__ES_PRECISION;
    return SK_OK;
}

SKGLDEF skgl_caps skgl_get_caps(const skgl_context *ctx)
{
    skgl_caps c;
    if (ctx) return ctx->caps;
    memset(&c, 0, sizeof c);
    return c;
}

/* skgl_create's desc, field by field: the message to the desc's logger
   (there is no context to keep it yet) */
static sk_result skgl__create_fail(const skgl_desc *desc, sk_result r, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (desc && desc->logger.func) desc->logger.func(desc->logger.user, SKGL_LOG_ERROR, msg);
    return r;
}

static sk_result skgl__create_desc(const skgl_desc *desc, skgl_context **out)
{
    static const char fn[] = "skgl_create";
    if (!desc) return SK_ERR_INVALID_ARG;   /* no logger to tell */
    if (!out) return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: out is NULL", fn);
    if (!desc->getproc)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG,
                                 "%s: desc.getproc is NULL: a function that returns GL entry points by name "
                                 "(glfwGetProcAddress, eglGetProcAddress, ...) is required", fn);
    if (desc->timing < 0 || desc->timing > SKGL_TIMING_SYNC)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: desc.timing = %d: 0, 1 or SKGL_TIMING_SYNC (2)", fn,
                                 desc->timing);
    if (desc->clip_zero_to_one != 0 && desc->clip_zero_to_one != 1)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: desc.clip_zero_to_one = %d: 0 or 1", fn,
                                 desc->clip_zero_to_one);
    if (desc->debug != 0 && desc->debug != 1)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: desc.debug = %d: 0 or 1", fn, desc->debug);
    if (desc->caller_owns_state != 0 && desc->caller_owns_state != 1)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: desc.caller_owns_state = %d: 0 or 1", fn,
                                 desc->caller_owns_state);
    if ((int)desc->api < SKGL_API_AUTO || (int)desc->api > SKGL_API_GLES3)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: desc.api = %d: one of skgl_api", fn, (int)desc->api);
    if (desc->disable_caps & ~0x07FFu)
        return skgl__create_fail(desc, SK_ERR_INVALID_ARG, "%s: desc.disable_caps = 0x%x: SKGL_CAP_* bits only", fn,
                                 desc->disable_caps);
    return SK_OK;
}

/* the required entry points through desc.getproc; the first missing one named */
static sk_result skgl__load(skgl_context *ctx, const skgl_desc *desc)
{
    /* void* -> function pointer through memcpy: ISO C has no direct cast */
#define SKGL__X(ret, name, args) { void *p_ = desc->getproc("gl" #name); \
        memcpy(&ctx->gl.name, &p_, sizeof p_); \
        if (!p_) return skgl__fail(ctx, SK_ERR_GL, "skgl_create: desc.getproc(\"gl%s\") returned NULL: " \
                                   "shadowkit needs it (an OpenGL 3.3 core or ES 3.0 context current?)", #name); }
    SKGL__FUNCS(SKGL__X)
#undef SKGL__X
    return SK_OK;
}

/* the programs every directional light needs (the depth pass, the mask);
   a technique's own are built with its first light (skgl__ferko_programs,
   skgl__rmsm_programs, skgl__evsm_programs); the first that fails has the
   driver's message in the log */
static sk_result skgl__create_programs(skgl_context *ctx)
{
    ctx->depth_prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_DEPTH_VERT), skgl__glsl(SKGL__GLSL_DEPTH_FRAG), NULL);
    if (ctx->depth_prog)
        ctx->mask_prog = skgl__mask_program(ctx, 0);
    if (ctx->mask_prog) return SK_OK;
    return skgl__programs_failed(ctx, "skgl_create: shadowkit's own shaders");
}

SKGLDEF sk_result skgl_create(const skgl_desc *desc, skgl_context **out)
{
    skgl_context *ctx;
    skgl__st st;
    skgl__int major = 0, minor = 0;
    skgl__enum e;
    sk_result r;
    if (out) *out = NULL;
    SKGL__TRY(skgl__create_desc(desc, out));
    ctx = (skgl_context *)SKGL_MALLOC(sizeof *ctx);
    if (!ctx) return skgl__create_fail(desc, SK_ERR_CAPACITY, "skgl_create: out of memory (%u bytes)",
                                       (unsigned)sizeof *ctx);
    memset(ctx, 0, sizeof *ctx);
    ctx->logger = desc->logger;
    ctx->model_loc = -1;   /* no caster pass under way */
    r = skgl__load(ctx, desc);
    if (r != SK_OK) { SKGL_FREE(ctx); return r; }
    skgl__pending_errors(ctx, "skgl_create");
    ctx->gl.GetIntegerv(SKGL__MAJOR_VERSION, &major);
    ctx->gl.GetIntegerv(SKGL__MINOR_VERSION, &minor);
    /* a context below 3.0 does not know GL_MAJOR_VERSION (GL_INVALID_ENUM, 0 read): the string says */
    if (major == 0) (void)ctx->gl.GetError();
    r = skgl__probe_caps(ctx, desc, major, minor);
    if (r != SK_OK) { SKGL_FREE(ctx); return r; }
    ctx->debug = desc->debug;
    ctx->timing = ctx->caps.timer_query ? desc->timing : 0;
    ctx->caller_owns = desc->caller_owns_state != 0;
    ctx->clip_zero_to_one = desc->clip_zero_to_one;
    if (ctx->clip_zero_to_one) {   /* its passes draw under OpenGL's clip depth, then give zero-to-one back */
        const char *name = ctx->caps.api == SKGL_API_GLES3 ? "glClipControlEXT" : "glClipControl";
        void *p_ = ctx->caps.clip_control ? desc->getproc(name) : NULL;
        if (!p_) {
            r = skgl__fail(ctx, SK_ERR_GL, "skgl_create: desc.clip_zero_to_one = 1 needs %s (OpenGL 4.5, "
                           "GL_ARB_clip_control, GL_EXT_clip_control on ES), %s", name,
                           ctx->caps.clip_control ? "which desc.getproc did not return" : "which this context lacks");
            SKGL_FREE(ctx);
            return r;
        }
        memcpy(&ctx->ClipControl, &p_, sizeof p_);
    }
    r = skgl__create_programs(ctx);
    if (r != SK_OK) {
        skgl__release(ctx);
        SKGL_FREE(ctx);
        return r;
    }
    skgl__st_begin(ctx, &st);
    skgl__own_programs(ctx, &st);
    skgl__st_end(ctx, &st);
    ctx->gl.GenVertexArrays(1, &ctx->empty_vao); ctx->objects++;
    ctx->gl.GenFramebuffers(1, &ctx->mask_fbo); ctx->objects++;
    ctx->cmp_sampler = skgl__sampler(ctx, 1);
    ctx->point_sampler = skgl__sampler(ctx, 0);
    e = ctx->gl.GetError();
    if (e != 0) {
        r = skgl__fail(ctx, SK_ERR_GL, "skgl_create: %s while creating the context's programs, samplers and "
                       "framebuffer", skgl__gl_error_name(e));
        while (ctx->gl.GetError() != 0 && ++major < 64) {}
        skgl__release(ctx);
        SKGL_FREE(ctx);
        return r;
    }
    skgl__log_clear(ctx);   /* a pending error's warning went to the logger; the log starts empty */
    *out = ctx;
    return SK_OK;
}

static void skgl__casters_release(skgl_context *ctx);

SKGLDEF void skgl_destroy(skgl_context *ctx)
{
    if (!ctx) return;
    skgl__casters_release(ctx);
    skgl__release(ctx);
    SKGL_FREE(ctx);
}

SKGLDEF int skgl_gl_object_count(const skgl_context *ctx) { return ctx ? ctx->objects : 0; }
SKGLDEF const char *skgl_error_log(const skgl_context *ctx) { return ctx ? ctx->log : ""; }

/* desc.debug: a GL error raised by the call (the application's were
   cleared on entry, skgl__enter), named, with the pass it came from */
static sk_result skgl__check(skgl_context *ctx, const char *what)
{
    skgl__enum e;
    int n = 0;
    if (!ctx->debug) return SK_OK;
    e = ctx->gl.GetError();
    if (e == 0) return SK_OK;
    while (ctx->gl.GetError() != 0 && ++n < 8) {}
    return skgl__fail(ctx, SK_ERR_GL, "%s: %s raised in %s", what, skgl__gl_error_name(e),
                      ctx->stage ? ctx->stage : "the call's own state changes");
}


/* ---- 5. Shared pass helpers --------------------------------------------- */
// >>passes
// >>lifecycle
/* One lifecycle for every kind of light (shadow, point,
   soft): create opens like every create (skgl__create_open), fills the
   defaults, checks every rule of the desc (one message per broken rule,
   naming the field), makes its GL objects inside one state-tracked call
   and on any failure gives everything back through its destroy
   (skgl__create_close); destroy gives back its GL objects (the kind's free
   function) and the struct, and does nothing without a context (the GL
   objects need it); get_desc is the filled desc (zeros for NULL); stats
   the last frame's (NULL for NULL). */

/* 5.1 the lights' objects (made inside a state-tracked call) */
/* a 2D texture (target 2D) or 2-layer array (layers 2), nearest filtering,
   made on unit 0; data: level 0's texels or NULL */
static skgl__uint skgl__color_texture(skgl_context *ctx, skgl__st *st, skgl__int ifmt, int w, int h, int layers,
                                      skgl__enum fmt, skgl__enum type, const void *data)
{
    skgl__api *gl = &ctx->gl;
    skgl__uint t = 0;
    int k = layers > 1 ? SKGL__T_2D_ARRAY : SKGL__T_2D;
    skgl__enum target = skgl__tex_targets[k];
    gl->GenTextures(1, &t);
    ctx->objects++;
    skgl__st_unpack(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, k), (skgl__int)t);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, k));
    if (layers > 1) gl->TexImage3D(target, 0, ifmt, w, h, layers, 0, fmt, type, data);
    else gl->TexImage2D(target, 0, ifmt, w, h, 0, fmt, type, data);
    /* no mipmaps: a mipmapped minification filter would leave it incomplete,
       and texelFetch of an incomplete texture reads 0 */
    gl->TexParameteri(target, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST);
    gl->TexParameteri(target, SKGL__TEXTURE_MAG_FILTER, SKGL__NEAREST);
    return t;
}

/* A framebuffer with colour attachment 0 (and 1: the second layer of a
   2-layer array texture), or with depth only (depth: a layer of a 2D array
   texture, or a 2D texture when layer < 0), checked complete here, once:
   the passes only bind it. glDrawBuffer(s) and glReadBuffer are state of
   the framebuffer object, set here too. 0 when it is not complete. */
#define SKGL__ALL_LAYERS (-2)   /* skgl__framebuffer's depth_layer: the whole texture, layered */
/* no colour output (ES 3.0 has glDrawBuffers only) */
static void skgl__draw_buffers_none(skgl_context *ctx)
{
    static const skgl__enum none = SKGL__NONE;
    ctx->gl.DrawBuffers(1, &none);
}
static skgl__uint skgl__framebuffer(skgl_context *ctx, skgl__st *st, skgl__uint color, int color_layers,
                                    skgl__uint depth, int depth_layer)
{
    static const skgl__enum bufs[2] = {SKGL__COLOR_ATTACHMENT0, SKGL__COLOR_ATTACHMENT1};
    skgl__api *gl = &ctx->gl;
    skgl__uint fb = 0;
    skgl__enum status;
    gl->GenFramebuffers(1, &fb);
    ctx->objects++;
    /* bound to both targets: glReadBuffer below sets the READ framebuffer's
       state, which must be this one, not the caller's */
    skgl__st_framebuffer(ctx, st, fb);
    if (color && color_layers > 1) {
        gl->FramebufferTextureLayer(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT0, color, 0, 0);
        gl->FramebufferTextureLayer(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT1, color, 0, 1);
        gl->DrawBuffers(2, bufs);
    } else if (color) {
        gl->FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT0, SKGL__TEXTURE_2D, color, 0);
    } else {
        if (depth_layer >= 0)
            gl->FramebufferTextureLayer(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT, depth, 0, depth_layer);
        else if (depth_layer == SKGL__ALL_LAYERS)   /* layered: gl_Layer picks the layer */
            gl->FramebufferTexture(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT, depth, 0);
        else gl->FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT, SKGL__TEXTURE_2D, depth, 0);
        skgl__draw_buffers_none(ctx);
        gl->ReadBuffer(SKGL__NONE);
    }
    status = gl->CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER);
    if (status != SKGL__FRAMEBUFFER_COMPLETE) {
        gl->DeleteFramebuffers(1, &fb);
        ctx->objects--;
        /* the tracked binding named the framebuffer just deleted: GL fell back to 0 */
        st->cur[SKGL__S_DRAW_FB][0] = 0;
        st->cur[SKGL__S_READ_FB][0] = 0;
        return 0;
    }
    return fb;
}

static void skgl__delete_texture(skgl_context *ctx, skgl__uint *t)
{
    if (*t) { ctx->gl.DeleteTextures(1, t); ctx->objects--; *t = 0; }
}
static void skgl__delete_framebuffer(skgl_context *ctx, skgl__uint *f)
{
    if (*f) { ctx->gl.DeleteFramebuffers(1, f); ctx->objects--; *f = 0; }
}

/* 5.2 large worlds: directional passes relative to an origin near the camera ---
   A float holds 24 bits: at 1e5 from the world origin a position is good
   to 8 mm, and a matrix that takes such positions to light clip space
   subtracts nearly equal large numbers. The directional passes therefore
   work relative to an origin: the camera's position rounded to a multiple
   of SKGL_ORIGIN_CELL on each axis (exact in float, so a float world
   position minus it is exact; zero within half a cell of the world origin,
   where everything is as without it). Crops are fitted to the camera and
   the scene bounds taken relative to it, the depth pass moves the models
   there (T(-origin) * model, in double), the mask reconstructs positions
   relative to its camera's origin, and matrices cross between origins in
   double (skgl__shift). Stable crops snap in world light space
   (sk_stable_crop_origin), so the texel grid does not move with the
   origin. What the API returns and takes is world space, as before. */
#ifndef SKGL_ORIGIN_CELL
#define SKGL_ORIGIN_CELL 256.0        /* <= 0: always the world origin */
#endif
static const double skgl__zero3[3] = {0.0, 0.0, 0.0};

/* the eye of a rigid view matrix, -R^T t, in double */
static void skgl__view_eye(const sk_mat4 *view, double eye[3])
{
    int k;
    for (k = 0; k < 3; k++)
        eye[k] = -((double)view->m[k * 4] * view->m[12] + (double)view->m[k * 4 + 1] * view->m[13] +
                   (double)view->m[k * 4 + 2] * view->m[14]);
}

/* 1 when the camera turned: a rotation element of a differs from b's by
   more than tol (0.03: about 1.7 degrees; 0.5: about 30) */
static int skgl__view_turned(const sk_mat4 *a, const sk_mat4 *b, float tol)
{
    int r, c;
    for (c = 0; c < 3; c++)
        for (r = 0; r < 3; r++)
            if (!(SK_FABSF(a->m[c * 4 + r] - b->m[c * 4 + r]) <= tol)) return 1;
    return 0;
}

static double skgl__dist2(const double a[3], const double b[3])
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}

static void skgl__origin(const sk_mat4 *view, double o[3])
{
    const double cell = SKGL_ORIGIN_CELL;
    double eye[3];
    int k;
    skgl__view_eye(view, eye);
    for (k = 0; k < 3; k++) {
        o[k] = cell > 0.0 ? SK_FLOOR(eye[k] / cell + 0.5) * cell : 0.0;
        if (!(SK_FABS(o[k]) < 1e30)) o[k] = 0.0;
    }
}

/* m * T(to - from), in double: takes p - to where m took p - from (m itself when from == to) */
static sk_mat4 skgl__shift(const sk_mat4 *m, const double from[3], const double to[3])
{
    sk_mat4 r = *m;
    double d0 = to[0] - from[0], d1 = to[1] - from[1], d2 = to[2] - from[2];
    int k;
    if (d0 == 0.0 && d1 == 0.0 && d2 == 0.0) return r;
    for (k = 0; k < 4; k++)
        r.m[12 + k] = (float)((double)m->m[12 + k] + (double)m->m[k] * d0 + (double)m->m[4 + k] * d1 +
                              (double)m->m[8 + k] * d2);
    return r;
}

static skgl_camera skgl__camera_rel(const skgl_camera *cam, const double o[3])
{
    skgl_camera c = *cam;
    c.view = skgl__shift(&cam->view, skgl__zero3, o);
    return c;
}

static skgl_scene skgl__scene_rel(const skgl_scene *scene, const double o[3])
{
    skgl_scene r = *scene;
    r.bounds.min = sk__v3((float)(scene->bounds.min.x - o[0]), (float)(scene->bounds.min.y - o[1]),
                          (float)(scene->bounds.min.z - o[2]));
    r.bounds.max = sk__v3((float)(scene->bounds.max.x - o[0]), (float)(scene->bounds.max.y - o[1]),
                          (float)(scene->bounds.max.z - o[2]));
    return r;
}

/* the pass's program current again before a uniform is sent to it, when
   a callback may have left another (skgl__after_draw) */
static void skgl__pass_program(skgl_context *ctx)
{
    if (!ctx->prog_unsure) return;
    ctx->prog_unsure = 0;
    if (!ctx->cur_caster) ctx->gl.UseProgram(ctx->pass_prog);
}

/* the current pass's model matrix (model_loc): T(-model_origin) * model, in double */
static void skgl__model(skgl_context *ctx, const float model[16])
{
    const double *o = ctx->model_origin;
    float r[16];
    int c, k;
    skgl__pass_program(ctx);
    if (o[0] == 0.0 && o[1] == 0.0 && o[2] == 0.0) {
        ctx->gl.UniformMatrix4fv(ctx->model_loc, 1, 0, model);
        return;
    }
    for (c = 0; c < 4; c++) {
        for (k = 0; k < 3; k++) r[c * 4 + k] = (float)((double)model[c * 4 + k] - o[k] * model[c * 4 + 3]);
        r[c * 4 + 3] = model[c * 4 + 3];
    }
    ctx->gl.UniformMatrix4fv(ctx->model_loc, 1, 0, r);
}

SKGLDEF void skgl_set_model(skgl_context *ctx, const float model[16])
{
    if (!ctx || !model || ctx->model_loc < 0) return;   /* outside a caster pass: nothing to set */
    skgl__model(ctx, model);
    /* the pass sets its identity again before the next callback (a caster's
       program gets its identity from skgl_use_caster) */
    if (!ctx->cur_caster) ctx->model_dirty = 1;
}

SKGLDEF const char *skgl_glsl_snippet(void) { return skgl__glsl(SKGL__GLSL_SHADOW_SAMPLE_GLSL); }

SKGLDEF int skgl_glsl_snippet_prefixed(const char *prefix, char *out, int cap)
{
    return skgl__glsl_prefixed(skgl__glsl(SKGL__GLSL_SHADOW_SAMPLE_GLSL), prefix, out, cap);
}

/* 5.3 the draw callback ---------------------------------------------------
   A caster pass binds the depth program and sets the model matrix once;
   the callback may set models (skgl_set_model) and bind its own program if
   it binds info->program again before it returns (the manual's SCENE
   ACCESS). After each callback the identity model is set again only if
   the callback set a model; with desc.debug, the program it left current
   is checked. The vertex array it may have bound and the unit it may have
   made active are no longer known (the default mode puts the caller's
   vertex array back at the end). */
static const float skgl__identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* a caster pass with program prog (current) begins: its view-projection
   and model locations, the identity model (relative to origin) */
static void skgl__model_begin(skgl_context *ctx, skgl__uint prog, skgl__int vp_loc, skgl__int model_loc,
                              int variant, const double origin[3])
{
    memcpy(ctx->model_origin, origin, sizeof ctx->model_origin);
    ctx->pass_prog = prog;
    ctx->pass_vp_loc = vp_loc;
    ctx->pass_model_loc = model_loc;
    ctx->pass_variant = variant;
    ctx->model_loc = model_loc;
    ctx->prog_unsure = 0;   /* prog was just bound through the tracker */
    skgl__model(ctx, skgl__identity);
    ctx->model_dirty = 0;
}

/* the caster passes are over: skgl_set_model does nothing until the next */
static void skgl__model_end(skgl_context *ctx)
{
    memcpy(ctx->model_origin, skgl__zero3, sizeof ctx->model_origin);
    ctx->model_loc = -1;
    ctx->prog_unsure = 0;   /* the tracker binds the next program itself (skgl__after_draw) */
}

/* What a draw callback must leave as it found it (SCENE ACCESS), checked
   with desc.debug: each item shadowkit has set in this call, GL's value
   against the one set. The first that differs is named in the log and
   set back. */
static const struct skgl__kept {
    int item;
    const char *name;
} skgl__callback_keeps[] = {
    {SKGL__S_DRAW_FB, "the draw framebuffer"}, {SKGL__S_VIEWPORT, "the viewport"},
    {SKGL__S_SCISSOR_TEST, "the scissor test"}, {SKGL__S_SCISSOR_BOX, "the scissor box"},
    {SKGL__S_DEPTH_TEST, "the depth test"}, {SKGL__S_DEPTH_FUNC, "the depth function"},
    {SKGL__S_DEPTH_MASK, "the depth write mask"}, {SKGL__S_DEPTH_CLAMP, "depth clamping"},
    {SKGL__S_POLY_FILL, "polygon offset (GL_POLYGON_OFFSET_FILL)"}, {SKGL__S_POLY_OFFSET, "the polygon offset"},
    {SKGL__S_POLYGON_MODE, "the polygon mode"}, {SKGL__S_BLEND, "blending"},
    {SKGL__S_BLEND_EQ, "the blend equation"}, {SKGL__S_COLOR_MASK, "the colour mask"}};

static skgl__uint skgl__caster_current(const skgl_context *ctx);

static sk_result skgl__callback_check(skgl_context *ctx, skgl__st *st)
{
    size_t k;
    skgl__int cur = 0, v[4];
    ctx->gl.GetIntegerv(SKGL__CURRENT_PROGRAM, &cur);
    if (cur != (skgl__int)skgl__caster_current(ctx)) {
        skgl__set_log(ctx, "the draw callback returned with another program current",
                      "bind info->program again before returning, or select caster programs "
                      "with skgl_use_caster");
        ctx->gl.UseProgram(ctx->pass_prog);
        return SK_ERR_INVALID_ARG;
    }
    for (k = 0; k < sizeof skgl__callback_keeps / sizeof skgl__callback_keeps[0]; k++) {
        int item = skgl__callback_keeps[k].item;
        if (!(st->flags[item] & SKGL__S_KNOWN)) continue;
        v[0] = v[1] = v[2] = v[3] = 0;
        skgl__st_query(&ctx->gl, item, v);
        if (memcmp(v, st->cur[item], sizeof(skgl__int) * (size_t)skgl__st_n(item)) == 0) continue;
        skgl__st_apply(&ctx->gl, item, st->cur[item]);
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "the draw callback changed %s: a callback leaves the framebuffer, viewport, scissor, "
                          "depth, blend and polygon state as it found them (SCENE ACCESS)",
                          skgl__callback_keeps[k].name);
    }
    return SK_OK;
}

static sk_result skgl__after_draw(skgl_context *ctx, skgl__st *st)
{
    sk_result r = ctx->debug ? skgl__callback_check(ctx, st) : SK_OK;
    if (ctx->cur_caster) {   /* the pass's own program again, as the tracker has it */
        ctx->gl.UseProgram(ctx->pass_prog);
        ctx->cur_caster = NULL;
        ctx->model_loc = ctx->pass_model_loc;
    } else if (!ctx->debug) {
        /* unchecked, the callback may have left a program of its own
           current (against SCENE ACCESS): the pass's program is bound
           again before shadowkit sends it a uniform (skgl__pass_program),
           and the tracker binds the next program it wants whatever it
           thinks is current, so nothing of shadowkit's lands in a foreign
           program */
        ctx->prog_unsure = 1;
        skgl__st_forget(st, SKGL__S_PROGRAM);
    }
    if (r == SK_OK) r = ctx->pass_error;
    ctx->pass_error = SK_OK;
    if (ctx->model_dirty) {
        skgl__model(ctx, skgl__identity);
        ctx->model_dirty = 0;
    }
    /* what the callback may change (SCENE ACCESS) is no longer known: the
       vertex array, the active unit (what shadowkit set on a unit before is
       then put back on the right one), culling, the pixel buffer bindings */
    skgl__st_forget(st, SKGL__S_VAO);
    skgl__st_forget(st, SKGL__S_ACTIVE);
    skgl__st_forget(st, SKGL__S_CULL_FACE);
    skgl__st_forget(st, SKGL__S_PACK_BUFFER);
    skgl__st_forget(st, SKGL__S_UNPACK_BUFFER);
    return r;
}

// >>caster_pass
/* Every caster pass of the directional and point lights
   goes through these two. skgl__casters_begin, once per call: the depth
   pass's state (skgl__st_depth_pass), shadowkit's depth program, the
   identity model (positions relative to origin), the caller's vertex array
   saved for the callback. skgl__casters_draw, per layer, page or face,
   into the target and viewport already set (and cleared): the pass's
   matrix, the callback with the matrix in world space, then what the
   callback may have changed. */
static void skgl__casters_begin_with(skgl_context *ctx, skgl__st *st, skgl__uint prog, skgl__int vp_loc,
                                     skgl__int model_loc, int variant, float slope_bias, float depth_bias,
                                     const double origin[3])
{
    skgl__st_save(ctx, st, SKGL__S_VAO);   /* the callback may bind its own */
    skgl__st_depth_pass(ctx, st, slope_bias, depth_bias);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)prog);
    skgl__model_begin(ctx, prog, vp_loc, model_loc, variant, origin);
    ctx->stage = "the caster passes";
}
/* with shadowkit's depth program */
static void skgl__casters_begin(skgl_context *ctx, skgl__st *st, float slope_bias, float depth_bias,
                                const double origin[3])
{
    skgl__casters_begin_with(ctx, st, ctx->depth_prog, ctx->depth_u_view_proj, ctx->depth_u_model, SKGL__CV_DEPTH,
                             slope_bias, depth_bias, origin);
}

/* the scene's callbacks that ctx->draw_class names, each followed by what
   a callback may have changed: draw (info->dynamic 0), then the dynamic casters
   (info->dynamic 1) when the scene has one */
/* desc.debug: a GL error raised since the last check, named with the pass
   (kind and index) and whether the callback or shadowkit's set-up of the
   pass raised it */
static sk_result skgl__pass_gl_check(skgl_context *ctx, const skgl_draw_info *info, const char *when)
{
    static const char *const kinds[4] = {"directional layer", "cube face", "area light map", "camera G-buffer"};
    skgl__enum e;
    int n = 0;
    if (!ctx->debug || (e = ctx->gl.GetError()) == 0) return SK_OK;
    while (ctx->gl.GetError() != 0 && ++n < 8) {}
    return skgl__fail(ctx, SK_ERR_GL, "%s: %s raised %s of the caster pass of %s %d%s",
                      ctx->call ? ctx->call : "shadowkit", skgl__gl_error_name(e), when,
                      (unsigned)info->kind < 4u ? kinds[info->kind] : "kind ?", info->index,
                      info->layers > 0 ? " (layered)" : "");
}

static sk_result skgl__scene_draw(skgl_context *ctx, skgl__st *st, const skgl_scene *scene, skgl_draw_info *info)
{
    sk_result r = skgl__pass_gl_check(ctx, info, "in shadowkit's set-up"), rc;
    if (ctx->draw_class != SKGL__DRAW_DYNAMIC) {
        info->dynamic = 0;
        scene->draw(scene->user, info);
        rc = skgl__pass_gl_check(ctx, info, "in the draw callback (scene.draw)");
        if (r == SK_OK) r = rc;
        rc = skgl__after_draw(ctx, st);
        if (r == SK_OK) r = rc;
    }
    if (ctx->dyn.draw && ctx->draw_class != SKGL__DRAW_STATIC) {
        info->dynamic = 1;
        ctx->dyn.draw(ctx->dyn.user, info);
        rc = skgl__pass_gl_check(ctx, info, "in the dynamic casters' callback (skgl_set_dynamic)");
        if (r == SK_OK) r = rc;
        rc = skgl__after_draw(ctx, st);
        if (r == SK_OK) r = rc;
    }
    return r;
}

/* the callbacks one pass of the casters of cls (SKGL__DRAW_*) makes, what
   stats.passes counts: scene.draw unless only the dynamic casters are
   drawn, and skgl_set_dynamic's when there is one and it is drawn */
static int skgl__class_callbacks(const skgl_context *ctx, int cls)
{
    return (cls != SKGL__DRAW_DYNAMIC) + (cls != SKGL__DRAW_STATIC && ctx->dyn.draw != NULL);
}
/* ... and of every caster */
static int skgl__pass_callbacks(const skgl_context *ctx) { return skgl__class_callbacks(ctx, SKGL__DRAW_ALL); }

static sk_result skgl__casters_draw(skgl_context *ctx, skgl__st *st, const skgl_scene *scene, const sk_mat4 *vp,
                                    const double origin[3], skgl_draw_info *info)
{
    skgl__pass_program(ctx);
    ctx->gl.UniformMatrix4fv(ctx->pass_vp_loc, 1, 0, vp->m);
    memcpy(ctx->pass_vp, vp->m, sizeof ctx->pass_vp);
    ctx->pass_serial++;
    info->view_proj = skgl__shift(vp, origin, skgl__zero3);
    info->frustum = sk_frustum_from_matrix(info->view_proj);
    info->program = ctx->pass_prog;
    return skgl__scene_draw(ctx, st, scene, info);
}

#if !defined(SKGL_NO_CACHE) || !defined(SKGL_NO_RMSM)
/* One caster pass of a cached map (a directional layer, an RMSM page, a
   point face) into fb: the casters of cls (SKGL__DRAW_*) in rect (x, y,
   w, h; NULL: the whole target, full x full texels, unscissored), cleared
   first when clear; info names the pass (its rect is set here). The
   callbacks made are added to *passes, the texels drawn to *texels. */
static sk_result skgl__cached_pass(skgl_context *ctx, skgl__st *st, const skgl_scene *scene, const sk_mat4 *vp,
                                   const double origin[3], skgl__uint fb, const int *rect, int full, int cls,
                                   int clear, skgl_draw_info *info, int *passes, double *texels)
{
    sk_result r;
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)fb);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, rect != NULL);
    if (rect) skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, rect[0], rect[1], rect[2], rect[3]);
    if (clear) skgl__clear_depth(ctx);
    if (rect) memcpy(info->rect, rect, sizeof info->rect);
    ctx->draw_class = cls;
    r = skgl__casters_draw(ctx, st, scene, vp, origin, info);
    ctx->draw_class = SKGL__DRAW_ALL;
    *passes += skgl__class_callbacks(ctx, cls);
    *texels += rect ? (double)rect[2] * rect[3] : (double)full * full;
    return r;
}
#endif

// >>layered
/* Layered single-pass caster rendering (desc.layered): the
   layers of a directional light (array texture) or the faces of a cube map
   attached whole (glFramebufferTexture), one callback, and layered.geom
   sending each triangle to every layer with gl_Layer. The program is made
   the first time a layered pass runs: with GL_ARB_gpu_shader5, one
   geometry shader invocation per layer; otherwise (GL 3.3 core) one
   invocation loops over the layers. Defining SKGL_LAYERED_LOOP before the
   implementation keeps the loop everywhere (a driver whose invocations are
   slow; the tests run both). */
static const char skgl__gs_invocations[] = "#extension GL_ARB_gpu_shader5 : require\n#define SKGL_GS_INVOCATIONS 1\n";
static const char skgl__gs5_extension[] = "#extension GL_ARB_gpu_shader5 : require\n";

/* the layered depth program with the given start of its geometry shader */
static skgl__uint skgl__layered_program(skgl_context *ctx, const char *gs_start)
{
    skgl__uint sh[3];
    sh[0] = skgl__shader(ctx, SKGL__VERTEX_SHADER, "#define SKGL_LAYERED 1\n", skgl__glsl(SKGL__GLSL_DEPTH_VERT));
    sh[1] = sh[0] ? skgl__shader(ctx, SKGL__GEOMETRY_SHADER, gs_start, skgl__glsl(SKGL__GLSL_LAYERED_GEOM)) : 0;
    sh[2] = sh[1] ? skgl__shader(ctx, SKGL__FRAGMENT_SHADER, skgl__glsl(SKGL__GLSL_DEPTH_FRAG), NULL) : 0;
    return skgl__link(ctx, sh, 3);
}

/* 1 when layered passes can run (the program made now if need be); a
   context where neither geometry shader compiles keeps the per-layer passes */
static int skgl__layered_ready(skgl_context *ctx)
{
    char keep[sizeof ctx->log];
    if (ctx->layered_state != 0) return ctx->layered_state > 0;
    memcpy(keep, ctx->log, sizeof keep);   /* the first try may fail without GL_ARB_gpu_shader5 */
    ctx->log_quiet++;
#ifndef SKGL_LAYERED_LOOP
    ctx->layered_prog = skgl__layered_program(ctx, skgl__gs_invocations);
#endif
    ctx->layered_state = 2;
    if (!ctx->layered_prog) {
        ctx->layered_prog = skgl__layered_program(ctx, "");
        ctx->layered_state = ctx->layered_prog ? 1 : -1;
    }
    ctx->log_quiet--;
    memcpy(ctx->log, keep, sizeof keep);
    if (ctx->layered_state < 0) return 0;
    ctx->layered_u_model = ctx->gl.GetUniformLocation(ctx->layered_prog, "skgl_model");
    ctx->layered_u_vp = ctx->gl.GetUniformLocation(ctx->layered_prog, "skgl_layer_vp");
    ctx->layered_u_of = ctx->gl.GetUniformLocation(ctx->layered_prog, "skgl_layer_of");
    ctx->layered_u_count = ctx->gl.GetUniformLocation(ctx->layered_prog, "skgl_layer_count");
    return 1;
}

/* the layers of the pass under way into a layered program's uniforms */
static void skgl__layers_send(skgl_context *ctx, skgl__int vp, skgl__int of, skgl__int count)
{
    int n = ctx->pass_layers;
    if (vp >= 0) ctx->gl.UniformMatrix4fv(vp, n, 0, ctx->pass_layer_vp[0]);
    if (of >= 0) ctx->gl.Uniform1iv(of, n, ctx->pass_layer_of);
    skgl__u1i(&ctx->gl, count, n);
}

/* One callback for n layers: vps[i] (relative to origin) into layer
   layer_of[i] of the layered target already bound and cleared, through
   the layered program (current, skgl__casters_begin_layered); the
   callback's info->layer_index[i] is index_of[i] (RMSM: the page, not the
   layer of the batch target). */
static sk_result skgl__casters_draw_layered_as(skgl_context *ctx, skgl__st *st, const skgl_scene *scene,
                                               const sk_mat4 *vps, const int *layer_of, const int *index_of, int n,
                                               const double origin[3], skgl_draw_info *info)
{
    int i;
    sk_result r;
    skgl__pass_program(ctx);   /* RMSM's batches: the last callback may have left its own program current */
    ctx->pass_layers = n;
    for (i = 0; i < n; i++) {
        memcpy(ctx->pass_layer_vp[i], vps[i].m, sizeof vps[i].m);
        ctx->pass_layer_of[i] = layer_of[i];
        info->layer_index[i] = index_of[i];
        info->layer_view_proj[i] = skgl__shift(&vps[i], origin, skgl__zero3);
        info->layer_frustum[i] = sk_frustum_from_matrix(info->layer_view_proj[i]);
    }
    skgl__layers_send(ctx, ctx->layered_u_vp, ctx->layered_u_of, ctx->layered_u_count);
    memcpy(ctx->pass_vp, vps[0].m, sizeof ctx->pass_vp);
    ctx->pass_serial++;
    info->layers = n;
    info->index = -1;
    info->view_proj = info->layer_view_proj[0];
    info->frustum = info->layer_frustum[0];
    info->program = ctx->pass_prog;
    r = skgl__scene_draw(ctx, st, scene, info);
    ctx->pass_layers = 0;
    return r;
}
/* ... each layer's info->layer_index its own: a cascade, a cube face */
static sk_result skgl__casters_draw_layered(skgl_context *ctx, skgl__st *st, const skgl_scene *scene,
                                            const sk_mat4 *vps, const int *layer_of, int n, const double origin[3],
                                            skgl_draw_info *info)
{
    return skgl__casters_draw_layered_as(ctx, st, scene, vps, layer_of, layer_of, n, origin, info);
}

/* the caster passes' state with the layered program (skgl__casters_begin's) */
static void skgl__casters_begin_layered(skgl_context *ctx, skgl__st *st, float slope_bias, float depth_bias,
                                        const double origin[3])
{
    skgl__casters_begin_with(ctx, st, ctx->layered_prog, -1, ctx->layered_u_model, SKGL__CV_LAYERED, slope_bias,
                             depth_bias, origin);
}

// >>casters
#ifndef SKGL_NO_CASTERS
/* Caster programs (skgl_caster_*). A caster's hooks become one
   program per kind of caster pass, built from the same embedded sources as
   shadowkit's own (SKGL_CASTER in place of attribute 0, SKGL_CASTER_FRAGMENT
   calling the fragment hook first): the depth passes (depth.vert +
   depth.frag: every directional, point and area light map), the PVSM
   low-resolution pass (+ soft_cons.geom, whose varyings it forwards) and
   the area lights' own G-buffer. Each program is linked the first time it
   is needed; a use in a pass sends the pass's matrix and uniforms once per
   callback. */
#define SKGL__CASTER_VARYINGS 16

typedef struct skgl__caster_prog {
    skgl__uint prog;                       /* 0: not linked yet */
    int failed;                            /* its link failed once: not tried again */
    unsigned serial;                       /* ctx->pass_serial when the pass's uniforms were sent */
    skgl__int vp, model, texel, conservative, eye;
    skgl__int layer_vp, layer_of, layer_count;   /* SKGL__CV_LAYERED */
    int user[SKGL_CASTER_UNIFORMS];        /* desc.uniforms' locations */
} skgl__caster_prog;

struct skgl_caster {
    struct skgl_caster *next;
    char *text;                            /* one block: the hooks, varyings and names, copied */
    const char *vertex, *fragment, *varyings, *label;
    const char *names[SKGL_CASTER_UNIFORMS];
    char *gen;                             /* one block: the texts below (NULL without varyings) */
    const char *decl_out, *decl_in;        /* the varyings as plain outputs and inputs */
    const char *block_out, *block_in;      /* the same as an interface block's members (a geometry
                                              shader follows the vertex stage, or precedes the fragment) */
    const char *gs_blocks;                 /* the geometry shaders' input and output blocks */
    const char *forward;                   /* the geometry shaders' skgl_caster_varyings() */
    char *undef_vertex, *undef_fragment;   /* #undef of each macro the hook defines, or NULL */
    skgl__caster_prog v[SKGL__CV_COUNT];
};

static skgl__uint skgl__caster_current(const skgl_context *ctx)
{
    return ctx->cur_caster ? ctx->cur_caster->v[ctx->pass_variant].prog : ctx->pass_prog;
}

/* desc.varyings parsed (skgl__varyings_parse): each declaration
   `[interpolation] [centroid] [precision] type name;` and each preprocessor
   line between them, in order, comments removed. The texts each stage gets
   are made from these (skgl__varyings_text), so that every stage sees the
   same declarations in the order and the dialect it needs: plain outputs
   and inputs, an interface block's members, the geometry shaders'
   forwarding function, each declaration after a #line naming its line. */
#define SKGL__VARYINGS_LINE0 20000     /* desc.varyings' line n is reported as 20000 + n */
enum { SKGL__VI_NONE, SKGL__VI_FLAT, SKGL__VI_SMOOTH, SKGL__VI_NOPERSPECTIVE };
typedef struct skgl__vitem {
    int line;                          /* in desc.varyings, from 1 */
    const char *pp;                    /* a preprocessor line (pp_len chars), or NULL: a declaration */
    size_t pp_len;
    const char *def;                   /* a #define's macro name (def_len chars), else NULL */
    size_t def_len;
    int interp, centroid;              /* SKGL__VI_*; 1: centroid */
    const char *prec, *type, *name;    /* prec NULL: none */
    size_t prec_len, type_len, name_len;
} skgl__vitem;

static int skgl__is_word(const char *s, size_t n, const char *w) { return strlen(w) == n && memcmp(s, w, n) == 0; }
static int skgl__ident_start(char c) { return isalpha((unsigned char)c) || c == '_'; }
static int skgl__ident_char(char c) { return isalnum((unsigned char)c) || c == '_'; }

/* comments out of t (in place: blanks, newlines kept so that lines keep
   their numbers); 0, or the line of a comment that does not end */
static int skgl__varyings_uncomment(char *t)
{
    int line = 1, open_line = 0;
    char *p;
    for (p = t; *p; p++) {
        if (open_line) {
            if (p[0] == '*' && p[1] == '/') { p[0] = p[1] = ' '; p++; open_line = 0; }
            else if (*p != '\n') *p = ' ';
        } else if (p[0] == '/' && p[1] == '/') {
            while (*p && *p != '\n') *p++ = ' ';
            if (!*p) break;
        } else if (p[0] == '/' && p[1] == '*') {
            p[0] = p[1] = ' ';
            p++;
            open_line = line;
        }
        if (*p == '\n') line++;
    }
    return open_line;
}

/* the declaration of tokens tok[0..n) (identifiers: qualifiers, type, name)
   into *it; SK_ERR_INVALID_ARG (logged, the line named) when it is not one */
static sk_result skgl__varyings_decl(skgl_context *ctx, const char *const *tok, const size_t *len, int n, int line,
                                     skgl__vitem *it)
{
    static const char fn[] = "skgl_caster_create";
    static const char *const ints[] = {"int", "uint", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4"};
    int i, interp = 0, k;
    memset(it, 0, sizeof *it);
    it->line = line;
    if (n < 2)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "%s: desc.varyings line %d: \"%.*s;\" is not a declaration `[qualifiers] type name;`", fn,
                          line, (int)len[0], tok[0]);
    for (i = 0; i < n - 2; i++) {
        const char *q = tok[i];
        size_t m = len[i];
        if (skgl__is_word(q, m, "flat") || skgl__is_word(q, m, "smooth") || skgl__is_word(q, m, "noperspective")) {
            if (interp)
                return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: two interpolation "
                                  "qualifiers before \"%.*s\"", fn, line, (int)len[n - 1], tok[n - 1]);
            interp = 1;
            it->interp = q[0] == 'f' ? SKGL__VI_FLAT : q[0] == 's' ? SKGL__VI_SMOOTH : SKGL__VI_NOPERSPECTIVE;
        } else if (skgl__is_word(q, m, "centroid") && !it->centroid) {
            it->centroid = 1;
        } else if ((skgl__is_word(q, m, "lowp") || skgl__is_word(q, m, "mediump") || skgl__is_word(q, m, "highp")) &&
                   !it->prec) {
            it->prec = q;
            it->prec_len = m;
        } else if (skgl__is_word(q, m, "in") || skgl__is_word(q, m, "out") || skgl__is_word(q, m, "varying")) {
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: \"%.*s\": shadowkit declares "
                              "each stage's in and out itself, leave them out", fn, line, (int)m, q);
        } else {
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: \"%.*s\" is not a qualifier of "
                              "a varying (flat, smooth, noperspective, centroid, lowp, mediump, highp; once each)",
                              fn, line, (int)m, q);
        }
    }
    it->type = tok[n - 2];
    it->type_len = len[n - 2];
    it->name = tok[n - 1];
    it->name_len = len[n - 1];
    if (skgl__is_word(it->type, it->type_len, "flat") || skgl__is_word(it->type, it->type_len, "smooth") ||
        skgl__is_word(it->type, it->type_len, "noperspective") || skgl__is_word(it->type, it->type_len, "centroid"))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: \"%.*s\" has no type", fn, line,
                          (int)it->name_len, it->name);
    for (k = 0; k < (int)(sizeof ints / sizeof ints[0]); k++)
        if (skgl__is_word(it->type, it->type_len, ints[k]) && it->interp != SKGL__VI_FLAT)
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: \"%.*s\": an integer varying "
                              "must be flat", fn, line, (int)it->name_len, it->name);
    if (skgl__is_word(it->name, it->name_len, "main") ||
        (it->name_len >= 5 && (memcmp(it->name, "skgl_", 5) == 0 || memcmp(it->name, "SKGL_", 5) == 0)) ||
        (it->name_len >= 3 && memcmp(it->name, "gl_", 3) == 0))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: \"%.*s\" is reserved (main, gl_*, "
                          "skgl_*, SKGL_*)", fn, line, (int)it->name_len, it->name);
    return SK_OK;
}

/* a preprocessor line, t[0] its '#', into *it; *end: where the line ends */
static sk_result skgl__varyings_pp(skgl_context *ctx, const char *t, int line, skgl__vitem *it, size_t *end)
{
    static const char *const ok[] = {"if", "ifdef", "ifndef", "elif", "else", "endif", "define", "undef"};
    size_t e = 0, w, k;
    int i;
    memset(it, 0, sizeof *it);
    it->line = line;
    while (t[e] && t[e] != '\n') e++;
    *end = e;
    if (e > 0 && t[e - 1] == '\\')
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_caster_create: desc.varyings line %d: a directive continued "
                          "on the next line (a trailing backslash) is not accepted", line);
    for (k = 1; t[k] == ' ' || t[k] == '\t'; k++) continue;
    for (w = k; skgl__ident_char(t[w]); w++) continue;
    for (i = 0; i < (int)(sizeof ok / sizeof ok[0]); i++)
        if (skgl__is_word(t + k, w - k, ok[i])) break;
    if (i == (int)(sizeof ok / sizeof ok[0]))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_caster_create: desc.varyings line %d: \"#%.*s\" is not "
                          "accepted (#if, #ifdef, #ifndef, #elif, #else, #endif, #define and #undef are)",
                          line, (int)(w - k), t + k);
    if (i == 6) {   /* #define: its name, undefined after the varyings */
        for (k = w; t[k] == ' ' || t[k] == '\t'; k++) continue;
        for (w = k; skgl__ident_char(t[w]); w++) continue;
        if (w == k || !skgl__ident_start(t[k]))
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_caster_create: desc.varyings line %d: #define without "
                              "a name", line);
        it->def = t + k;
        it->def_len = w - k;
    }
    while (e > 0 && isspace((unsigned char)t[e - 1])) e--;
    it->pp = t;
    it->pp_len = e;
    return SK_OK;
}

/* desc.varyings (t: a copy, uncommented in place) into items[0..*n), cap
   of them at most; SK_ERR_INVALID_ARG (logged, naming the line) when it is
   not a list of declarations `[qualifiers] type name;` and preprocessor
   lines */
static sk_result skgl__varyings_parse(skgl_context *ctx, char *t, skgl__vitem *items, int cap, int *n)
{
    static const char fn[] = "skgl_caster_create";
    const char *tok[8];
    size_t len[8], i = 0;
    int line = 1, line_start = 1, ntok = 0, tok_line = 1, decls = 0;
    int open = skgl__varyings_uncomment(t);
    *n = 0;
    if (open)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: a /* comment that does not end", fn,
                          open);
    while (t[i]) {
        char c = t[i];
        if (c == '\n') { line++; line_start = 1; i++; continue; }
        if (isspace((unsigned char)c)) { i++; continue; }
        if (c == '#') {
            size_t end;
            if (!line_start || ntok > 0)
                return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: a directive must begin its "
                                  "line, between declarations", fn, line);
            if (*n == cap) return skgl__fail(ctx, SK_ERR_CAPACITY, "%s: desc.varyings: too many lines", fn);
            SKGL__TRY(skgl__varyings_pp(ctx, t + i, line, &items[*n], &end));
            ++*n;
            i += end;
            continue;
        }
        line_start = 0;
        if (skgl__ident_start(c)) {
            if (ntok == 8)
                return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: a declaration of more than "
                                  "8 words", fn, tok_line);
            if (ntok == 0) tok_line = line;
            tok[ntok] = t + i;
            for (len[ntok] = 0; skgl__ident_char(t[i]); i++) len[ntok]++;
            ntok++;
            continue;
        }
        if (c == ';') {
            i++;
            if (ntok == 0) continue;   /* an empty declaration */
            if (++decls > SKGL__CASTER_VARYINGS)
                return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: more than %d varyings", fn,
                                  tok_line, SKGL__CASTER_VARYINGS);
            if (*n == cap) return skgl__fail(ctx, SK_ERR_CAPACITY, "%s: desc.varyings: too many lines", fn);
            /* a name declared twice is the compiler's to report (#if and #else
               may each declare it) */
            SKGL__TRY(skgl__varyings_decl(ctx, tok, len, ntok, tok_line, &items[*n]));
            ++*n;
            ntok = 0;
            continue;
        }
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: %s", fn, line,
                          c == ','   ? "one varying per declaration (not `float a, b;`: `float a; float b;`)"
                          : c == '[' ? "arrays are not accepted"
                          : c == '{' || c == '}' ? "blocks and structs are not accepted"
                                     : "a character outside `[qualifiers] type name;`");
    }
    if (ntok > 0)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.varyings line %d: the declaration does not end in ';'",
                          fn, tok_line);
    return SK_OK;
}

/* appends to a text being measured (p NULL: n counts) or written */
typedef struct skgl__sb {
    char *p;
    size_t n;
} skgl__sb;

static void skgl__sb_put(skgl__sb *b, const char *s, size_t n)
{
    if (b->p) memcpy(b->p + b->n, s, n);
    b->n += n;
}

static void skgl__sb_str(skgl__sb *b, const char *s) { skgl__sb_put(b, s, strlen(s)); }

/* skgl_in[0].name, in the forwarding function */
static void skgl__sb_in(skgl__sb *b, const skgl__vitem *it, int vertex)
{
    char s[24];
    sprintf(s, "skgl_in[%d].", vertex);
    skgl__sb_str(b, s);
    skgl__sb_put(b, it->name, it->name_len);
}

/* the varyings for one use, the preprocessor lines among them:
   dir "out " / "in ": declarations with that storage qualifier (plain, or
   an interface block's members); dir NULL: the statements of the
   geometry shaders' skgl_caster_varyings(skgl_b, skgl_s, skgl_k) (the
   weights of smooth and of noperspective varyings, the vertex of flat
   ones; skgl_in[] indexed by constants only). The varyings' own macros
   are undefined after them: they do not rewrite shadowkit's code, or the
   hooks. */
static void skgl__varyings_text(skgl__sb *b, const skgl__vitem *it, int n, const char *dir)
{
    static const char *const interp[4] = {"", "flat ", "smooth ", "noperspective "};
    char line[40];
    int i, v;
    for (i = 0; i < n; i++, it++) {
        if (it->pp) {
            skgl__sb_put(b, it->pp, it->pp_len);
            skgl__sb_str(b, "\n");
            continue;
        }
        sprintf(line, "#line %d 3\n", SKGL__VARYINGS_LINE0 + it->line);
        skgl__sb_str(b, line);
        if (!dir) {
            skgl__sb_str(b, "    skgl_out.");
            skgl__sb_put(b, it->name, it->name_len);
            if (it->interp == SKGL__VI_FLAT) {   /* the value of vertex skgl_k */
                for (v = 0; v < 2; v++) {
                    skgl__sb_str(b, v ? " : (skgl_k == 1 ? " : " = skgl_k == 0 ? ");
                    skgl__sb_in(b, it, v);
                }
                skgl__sb_str(b, " : ");
                skgl__sb_in(b, it, 2);
                skgl__sb_str(b, ");\n");
            } else {   /* noperspective: the window-space weights; smooth: the perspective-correct */
                const char *w = it->interp == SKGL__VI_NOPERSPECTIVE ? "skgl_s" : "skgl_b";
                for (v = 0; v < 3; v++) {
                    sprintf(line, "%s%s.%c * ", v ? " + " : " = ", w, "xyz"[v]);
                    skgl__sb_str(b, line);
                    skgl__sb_in(b, it, v);
                }
                skgl__sb_str(b, ";\n");
            }
            continue;
        }
        skgl__sb_str(b, interp[it->interp]);
        if (it->centroid) skgl__sb_str(b, "centroid ");
        skgl__sb_str(b, dir);
        if (it->prec) { skgl__sb_put(b, it->prec, it->prec_len); skgl__sb_str(b, " "); }
        skgl__sb_put(b, it->type, it->type_len);
        skgl__sb_str(b, " ");
        skgl__sb_put(b, it->name, it->name_len);
        skgl__sb_str(b, ";\n");
    }
    for (it -= n, i = 0; i < n; i++, it++)
        if (it->def) {
            skgl__sb_str(b, "#undef ");
            skgl__sb_put(b, it->def, it->def_len);
            skgl__sb_str(b, "\n");
        }
}

/* every text of the varyings the caster's stages use, one after another
   (b->p NULL: measured only); their starts into c when written */
static void skgl__caster_texts(skgl__sb *b, skgl_caster *c, const skgl__vitem *it, int n)
{
    const char **at[6];
    int k = 0;
    at[0] = &c->decl_out; at[1] = &c->decl_in; at[2] = &c->block_out; at[3] = &c->block_in;
    at[4] = &c->gs_blocks; at[5] = &c->forward;
#define SKGL__TEXT_START() do { if (b->p) *at[k] = b->p + b->n; k++; } while (0)
#define SKGL__TEXT_END() skgl__sb_put(b, "", 1)
    SKGL__TEXT_START(); skgl__varyings_text(b, it, n, "out "); SKGL__TEXT_END();
    SKGL__TEXT_START(); skgl__varyings_text(b, it, n, "in "); SKGL__TEXT_END();
    SKGL__TEXT_START();
    skgl__sb_str(b, "out skgl_caster_block {\n"); skgl__varyings_text(b, it, n, "out "); skgl__sb_str(b, "};\n");
    SKGL__TEXT_END();
    SKGL__TEXT_START();
    skgl__sb_str(b, "in skgl_caster_block {\n"); skgl__varyings_text(b, it, n, "in "); skgl__sb_str(b, "};\n");
    SKGL__TEXT_END();
    SKGL__TEXT_START();
    skgl__sb_str(b, "in skgl_caster_block {\n"); skgl__varyings_text(b, it, n, "in ");
    skgl__sb_str(b, "} skgl_in[];\nout skgl_caster_block {\n"); skgl__varyings_text(b, it, n, "out ");
    skgl__sb_str(b, "} skgl_out;\n");
    SKGL__TEXT_END();
    SKGL__TEXT_START();
    skgl__sb_str(b, "\nvoid skgl_caster_varyings(vec3 skgl_b, vec3 skgl_s, int skgl_k)\n{\n");
    skgl__varyings_text(b, it, n, NULL);
    skgl__sb_str(b, "}\n");
    SKGL__TEXT_END();
#undef SKGL__TEXT_START
#undef SKGL__TEXT_END
}

/* desc.varyings parsed into the caster's texts (c->gen); SK_ERR_INVALID_ARG
   (logged) when it does not parse, SK_ERR_CAPACITY without memory */
static sk_result skgl__caster_varyings(skgl_context *ctx, skgl_caster *c)
{
    size_t len = strlen(c->varyings), k;
    int cap = 1, n = 0;
    char *t;
    skgl__vitem *items;
    skgl__sb b;
    sk_result r;
    for (k = 0; k < len; k++) cap += c->varyings[k] == ';' || c->varyings[k] == '\n';
    t = (char *)SKGL_MALLOC(len + 1);
    items = (skgl__vitem *)SKGL_MALLOC(sizeof *items * (size_t)cap);
    if (!t || !items) {
        SKGL_FREE(t);
        SKGL_FREE(items);
        return skgl__fail(ctx, SK_ERR_CAPACITY, "skgl_caster_create: out of memory");
    }
    memcpy(t, c->varyings, len + 1);
    r = skgl__varyings_parse(ctx, t, items, cap, &n);
    for (k = 0; k < (size_t)n && items[k].pp; k++) continue;
    if (r == SK_OK && k < (size_t)n) {   /* no declaration: no texts */
        b.p = NULL;
        b.n = 0;
        skgl__caster_texts(&b, c, items, n);
        b.p = c->gen = (char *)SKGL_MALLOC(b.n);
        b.n = 0;
        if (b.p) skgl__caster_texts(&b, c, items, n);
        else r = skgl__fail(ctx, SK_ERR_CAPACITY, "skgl_caster_create: out of memory");
    }
    SKGL_FREE(t);
    SKGL_FREE(items);
    return r;
}

/* "#undef NAME\n" for each `#define NAME` line of a hook (*out NULL when
   there is none), so that the hook's macros end with it: shadowkit's code
   after it (swizzles such as .w and .xy included) is not rewritten by them.
   GL_, __ and SKGL_ names are left alone (GLSL's own; shadowkit's).
   SK_ERR_CAPACITY without memory. */
static sk_result skgl__hook_undefs(skgl_context *ctx, const char *hook, char **out)
{
    skgl__sb b;
    int pass;
    *out = NULL;
    b.p = NULL;
    for (pass = 0; pass < 2; pass++) {
        const char *p = hook;
        b.n = 0;
        while (*p) {
            const char *name, *e;
            while (*p == ' ' || *p == '\t') p++;
            if (*p == '#') {
                for (p++; *p == ' ' || *p == '\t'; p++) continue;
                if (strncmp(p, "define", 6) == 0 && (p[6] == ' ' || p[6] == '\t')) {
                    for (name = p + 6; *name == ' ' || *name == '\t'; name++) continue;
                    for (e = name; skgl__ident_char(*e); e++) continue;
                    if (e > name && skgl__ident_start(*name) && strncmp(name, "GL_", 3) != 0 &&
                        strncmp(name, "__", 2) != 0 && strncmp(name, "SKGL_", 5) != 0) {
                        skgl__sb_str(&b, "#undef ");
                        skgl__sb_put(&b, name, (size_t)(e - name));
                        skgl__sb_str(&b, "\n");
                    }
                }
            }
            while (*p && *p != '\n') p++;
            if (*p) p++;
        }
        if (b.n == 0) return SK_OK;
        if (pass == 0) {
            b.p = *out = (char *)SKGL_MALLOC(b.n + 1);
            if (!b.p) return skgl__fail(ctx, SK_ERR_CAPACITY, "skgl_caster_create: out of memory");
        }
    }
    b.p[b.n] = 0;
    return SK_OK;
}

/* compiles n strings (after #version) into a shader of the given type;
   0 with the log naming the caster and the stage on failure */
static skgl__uint skgl__caster_shader(skgl_context *ctx, const skgl_caster *c, skgl__enum type,
                                      const char *const *src, int n, const char *fn)
{
    char log[700];
    skgl__uint sh = skgl__shader_n(ctx, type, src, n, log, (int)sizeof log);
    if (!sh) {
        skgl__fail(ctx, SK_ERR_GL,
                   "%s: caster '%s': the %s does not compile (lines 1 to 10000 are the hook's own, from 10001 "
                   "shadowkit's pass, from 20001 desc.varyings' (20000 + its line); drivers that keep #line's "
                   "source number show 1 for the vertex hook, 2 for the fragment hook, 3 for desc.varyings): %s",
                   fn, c->label,
                   type == SKGL__VERTEX_SHADER     ? "vertex shader"
                   : type == SKGL__GEOMETRY_SHADER ? "geometry shader"
                                                   : "fragment shader",
                   log);
    }
    return sh;
}

/* links the caster's program for pass kind `variant`, finds its locations */
static sk_result skgl__caster_link(skgl_context *ctx, skgl_caster *c, int variant, const char *fn)
{
    static const char *passes[SKGL__CV_COUNT] = {"#define SKGL_CASTER_PASS 0\n", "#define SKGL_CASTER_PASS 1\n",
                                                 "#define SKGL_CASTER_PASS 2\n",
                                                 "#define SKGL_CASTER_PASS 0\n#define SKGL_LAYERED 1\n"};
    skgl__caster_prog *v = &c->v[variant];
    const char *src[11];
    skgl__uint sh[3] = {0, 0, 0};
    int gs = variant == SKGL__CV_CONS || variant == SKGL__CV_LAYERED;
    int n, k, stages = gs ? 3 : 2;
    const char *vs = skgl__glsl(variant == SKGL__CV_GBUF ? SKGL__GLSL_SOFT_GBUFFER_VERT : SKGL__GLSL_DEPTH_VERT);
    const char *fs = skgl__glsl(variant == SKGL__CV_GBUF   ? SKGL__GLSL_SOFT_GBUFFER_FRAG
                                : variant == SKGL__CV_CONS ? SKGL__GLSL_SOFT_CONS_FRAG
                                                           : SKGL__GLSL_DEPTH_FRAG);
    /* vertex: the varyings as an output block for a geometry shader (its
       members named as declared), plain outputs for a fragment shader;
       every stage defines the same SKGL_ macros before the varyings, so
       that their #if lines choose alike */
    n = 0;
    src[n++] = "#define SKGL_CASTER 1\n";
    src[n++] = passes[variant];
    if (c->gen) src[n++] = gs ? c->block_out : c->decl_out;
    src[n++] = "#line 1 1\n";
    src[n++] = c->vertex;
    src[n++] = "\n";
    if (c->undef_vertex) src[n++] = c->undef_vertex;
    src[n++] = "#line 10001 0\n";
    src[n++] = vs;
    sh[0] = skgl__caster_shader(ctx, c, SKGL__VERTEX_SHADER, src, n, fn);
    if (sh[0] && gs) {
        /* the forwarding function after the shader's own source, where its
           input layout has sized skgl_in[] (its prototype is there) */
        int invocations = variant == SKGL__CV_LAYERED && ctx->layered_state == 2;
        n = 0;
        if (invocations) src[n++] = skgl__gs5_extension;
        src[n++] = "#define SKGL_CASTER 1\n";
        src[n++] = passes[variant];
        if (c->gen) src[n++] = c->gs_blocks;
        if (c->gen) src[n++] = "#define SKGL_CASTER_VARYINGS 1\n";
        if (invocations) src[n++] = "#define SKGL_GS_INVOCATIONS 1\n";
        src[n++] = "#line 10001 0\n";
        src[n++] = skgl__glsl(variant == SKGL__CV_CONS ? SKGL__GLSL_SOFT_CONS_GEOM : SKGL__GLSL_LAYERED_GEOM);
        if (c->gen) src[n++] = c->forward;
        sh[1] = skgl__caster_shader(ctx, c, SKGL__GEOMETRY_SHADER, src, n, fn);
    }
    if (sh[0] && (stages == 2 || sh[1])) {
        n = 0;
        src[n++] = "#define SKGL_CASTER 1\n";
        src[n++] = passes[variant];
        if (c->gen) src[n++] = gs ? c->block_in : c->decl_in;
        if (c->fragment) {
            src[n++] = "#define SKGL_CASTER_FRAGMENT 1\n#line 1 2\n";
            src[n++] = c->fragment;
            src[n++] = "\n";
            if (c->undef_fragment) src[n++] = c->undef_fragment;
        }
        src[n++] = "#line 10001 0\n";
        src[n++] = fs;
        sh[stages - 1] = skgl__caster_shader(ctx, c, SKGL__FRAGMENT_SHADER, src, n, fn);
    }
    if (!gs) sh[2] = 0;
    v->prog = skgl__link(ctx, sh, stages);
    if (!v->prog) {
        v->failed = 1;
        if (sh[0] && sh[stages - 1]) {
            /* compiled, but the link failed: skgl__link's log, named (a copy:
               vsnprintf's source and destination must not overlap) */
            char link_log[sizeof ctx->log];
            memcpy(link_log, ctx->log, sizeof link_log);
            skgl__fail(ctx, SK_ERR_GL, "%s: caster '%s': %.900s", fn, c->label, link_log);
        }
        return SK_ERR_GL;
    }
    v->vp = ctx->gl.GetUniformLocation(v->prog, "skgl_view_proj");
    v->model = ctx->gl.GetUniformLocation(v->prog, "skgl_model");
    v->texel = ctx->gl.GetUniformLocation(v->prog, "skgl_texel");
    v->conservative = ctx->gl.GetUniformLocation(v->prog, "skgl_conservative");
    v->eye = ctx->gl.GetUniformLocation(v->prog, "skgl_eye");
    v->layer_vp = ctx->gl.GetUniformLocation(v->prog, "skgl_layer_vp");
    v->layer_of = ctx->gl.GetUniformLocation(v->prog, "skgl_layer_of");
    v->layer_count = ctx->gl.GetUniformLocation(v->prog, "skgl_layer_count");
    for (k = 0; k < SKGL_CASTER_UNIFORMS; k++)
        v->user[k] = c->names[k] ? ctx->gl.GetUniformLocation(v->prog, c->names[k]) : -1;
    v->serial = ctx->pass_serial - 1u;
    return SK_OK;
}

static void skgl__caster_free(skgl_context *ctx, skgl_caster *c)
{
    int k;
    for (k = 0; k < SKGL__CV_COUNT; k++)
        if (c->v[k].prog) {
            ctx->gl.DeleteProgram(c->v[k].prog);
            ctx->objects--;
        }
    SKGL_FREE(c->gen);
    SKGL_FREE(c->undef_vertex);
    SKGL_FREE(c->undef_fragment);
    SKGL_FREE(c->text);
    SKGL_FREE(c);
}

/* copies s into the block at *p (NULL stays NULL) */
static const char *skgl__caster_copy(char **p, const char *s)
{
    char *r = *p;
    size_t n;
    if (!s) return NULL;
    n = strlen(s) + 1;
    memcpy(r, s, n);
    *p += n;
    return r;
}

/* the desc's texts copied into the caster's block p, and its hooks parsed */
static sk_result skgl__caster_copy_desc(skgl_context *ctx, skgl_caster *c, const skgl_caster_desc *desc, char *p)
{
    sk_result r;
    int k;
    c->vertex = skgl__caster_copy(&p, desc->vertex);
    c->fragment = desc->fragment && desc->fragment[0] ? skgl__caster_copy(&p, desc->fragment) : NULL;
    c->varyings = desc->varyings && desc->varyings[0] ? skgl__caster_copy(&p, desc->varyings) : NULL;
    c->label = skgl__caster_copy(&p, desc->label ? desc->label : "caster");
    for (k = 0; k < SKGL_CASTER_UNIFORMS; k++) c->names[k] = skgl__caster_copy(&p, desc->uniforms[k]);
    if (c->varyings && (r = skgl__caster_varyings(ctx, c)) != SK_OK) return r;
    if ((r = skgl__hook_undefs(ctx, c->vertex, &c->undef_vertex)) != SK_OK) return r;
    return c->fragment ? skgl__hook_undefs(ctx, c->fragment, &c->undef_fragment) : SK_OK;
}

SKGLDEF sk_result skgl_caster_create(skgl_context *ctx, const skgl_caster_desc *desc, skgl_caster **out)
{
    static const char fn[] = "skgl_caster_create";
    skgl_caster *c;
    size_t bytes = 0;
    char *p;
    int k;
    sk_result r;
    if (out) *out = NULL;
    SKGL__TRY(skgl__create_open(ctx, fn, !desc, !out));
    if (!desc->vertex || !desc->vertex[0])
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "%s: desc.vertex is required: GLSL declaring vec4 skgl_caster_position(void)", fn);
    bytes += strlen(desc->vertex) + 1;
    bytes += desc->fragment ? strlen(desc->fragment) + 1 : 0;
    bytes += desc->varyings ? strlen(desc->varyings) + 1 : 0;
    bytes += strlen(desc->label ? desc->label : "caster") + 1;
    for (k = 0; k < SKGL_CASTER_UNIFORMS; k++) bytes += desc->uniforms[k] ? strlen(desc->uniforms[k]) + 1 : 0;
    c = (skgl_caster *)skgl__create_alloc(ctx, fn, sizeof *c);
    if (!c) return SK_ERR_CAPACITY;
    c->text = p = (char *)skgl__create_alloc(ctx, fn, bytes);
    r = p ? SK_OK : SK_ERR_CAPACITY;
    if (r == SK_OK) r = skgl__caster_copy_desc(ctx, c, desc, p);
    if (r == SK_OK) {
        ctx->log[0] = 0;
        r = skgl__caster_link(ctx, c, SKGL__CV_DEPTH, fn);
    }
    r = skgl__create_close(ctx, fn, r, "its depth program");
    if (r != SK_OK) {   /* not listed yet: skgl_caster_destroy would not find it */
        skgl__caster_free(ctx, c);
        return r;
    }
    c->next = ctx->casters;
    ctx->casters = c;
    *out = c;
    return SK_OK;
}

SKGLDEF void skgl_caster_destroy(skgl_context *ctx, skgl_caster *caster)
{
    skgl_caster **at;
    if (!ctx || !caster) return;
    for (at = &ctx->casters; *at && *at != caster; at = &(*at)->next) continue;
    if (!*at) return;   /* not this context's, or destroyed already */
    *at = caster->next;
    skgl__caster_free(ctx, caster);
}

/* every caster left, at skgl_destroy */
static void skgl__casters_release(skgl_context *ctx)
{
    while (ctx->casters) {
        skgl_caster *c = ctx->casters;
        ctx->casters = c->next;
        skgl__caster_free(ctx, c);
    }
}

/* the pass's uniforms into caster program v (bound), once per callback */
static void skgl__caster_send(skgl_context *ctx, skgl__caster_prog *v)
{
    skgl__api *gl = &ctx->gl;
    if (v->serial == ctx->pass_serial) return;
    v->serial = ctx->pass_serial;
    gl->UniformMatrix4fv(v->vp, 1, 0, ctx->pass_vp);
    if (ctx->pass_variant == SKGL__CV_CONS) {
        if (v->texel >= 0) gl->Uniform2fv(v->texel, 1, ctx->pass_texel);
        skgl__u1i(gl, v->conservative, ctx->pass_conservative);
    }
    if (ctx->pass_variant == SKGL__CV_GBUF && v->eye >= 0) gl->Uniform3fv(v->eye, 1, ctx->pass_eye);
    if (ctx->pass_variant == SKGL__CV_LAYERED) skgl__layers_send(ctx, v->layer_vp, v->layer_of, v->layer_count);
}

SKGLDEF const int *skgl_use_caster(skgl_context *ctx, skgl_caster *caster)
{
    static const int none[SKGL_CASTER_UNIFORMS] = {-1, -1, -1, -1, -1, -1, -1, -1,
                                                   -1, -1, -1, -1, -1, -1, -1, -1};
    skgl__caster_prog *v;
    if (!ctx) return NULL;
    if (ctx->model_loc < 0) {
        skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_use_caster: called outside a draw callback");
        return NULL;
    }
    if (caster == ctx->cur_caster) return caster ? caster->v[ctx->pass_variant].user : none;
    if (!caster) {
        ctx->gl.UseProgram(ctx->pass_prog);
        ctx->cur_caster = NULL;
        ctx->model_loc = ctx->pass_model_loc;
        if (ctx->model_dirty) {
            skgl__model(ctx, skgl__identity);
            ctx->model_dirty = 0;
        }
        return none;
    }
    v = &caster->v[ctx->pass_variant];
    if (!v->prog) {
        /* linked the first time this kind of pass needs it; a failed link is
           not tried again (its message was logged then) */
        if (v->failed) {
            if (ctx->pass_error == SK_OK)
                skgl__fail(ctx, SK_ERR_GL, "skgl_use_caster: caster '%s' has no program for this pass (its link "
                           "failed before)", caster->label);
            ctx->pass_error = SK_ERR_GL;
            return NULL;
        }
        if (skgl__caster_link(ctx, caster, ctx->pass_variant, "skgl_use_caster") != SK_OK) {
            ctx->pass_error = SK_ERR_GL;
            return NULL;
        }
    }
    ctx->gl.UseProgram(v->prog);
    ctx->cur_caster = caster;
    ctx->model_loc = v->model;
    skgl__caster_send(ctx, v);
    skgl__model(ctx, skgl__identity);
    return v->user;
}
#else /* SKGL_NO_CASTERS: the caster entry points refuse, naming the macro; no caster is ever current */
static skgl__uint skgl__caster_current(const skgl_context *ctx) { return ctx->pass_prog; }
static void skgl__casters_release(skgl_context *ctx) { (void)ctx; }
SKGLDEF sk_result skgl_caster_create(skgl_context *ctx, const skgl_caster_desc *desc, skgl_caster **out)
{
    (void)desc;
    if (out) *out = NULL;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__log_clear(ctx);
    return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_caster_create: compiled out (SKGL_NO_CASTERS)");
}
SKGLDEF void skgl_caster_destroy(skgl_context *ctx, skgl_caster *caster) { (void)ctx; (void)caster; }
SKGLDEF const int *skgl_use_caster(skgl_context *ctx, skgl_caster *caster)
{
    (void)caster;
    if (!ctx) return NULL;
    if (ctx->pass_error == SK_OK)   /* inside a callback the render returns it (skgl__after_draw) */
        skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_use_caster: compiled out (SKGL_NO_CASTERS)");
    if (ctx->model_loc >= 0) ctx->pass_error = SK_ERR_INVALID_ARG;
    return NULL;
}
#endif /* SKGL_NO_CASTERS */

/* 5.4 the masks' inputs ------------------------------------------------- */
/* The mask texture as the only colour target of the masks' framebuffer,
   attached by name at every call (a texture deleted and made again under
   the same name is a new object: an attachment kept from before would
   still name the old one), checked complete the first time the name comes
   by (skgl__texture); the full viewport and the state of a full-screen
   pass. *w, *h: the mask's size. */
static sk_result skgl__mask_begin(skgl_context *ctx, skgl__st *st, unsigned mask_tex, int *w, int *h,
                                  const char *fn)
{
    skgl__texent *e;
    const char *why = skgl__texture_size(ctx, st, mask_tex, w, h);
    if (why) {
        skgl__set_log(ctx, fn, why);
        return SK_ERR_INVALID_ARG;
    }
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)ctx->mask_fbo);
    ctx->gl.FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT0, SKGL__TEXTURE_2D, mask_tex, 0);
    ctx->mask_fbo_tex = mask_tex;
    e = skgl__texture(ctx, mask_tex);
    if (!e->fb_ok) {
        if (ctx->gl.CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) != SKGL__FRAMEBUFFER_COMPLETE) {
            ctx->gl.FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT0, SKGL__TEXTURE_2D, 0, 0);
            ctx->mask_fbo_tex = 0;
            skgl__set_log(ctx, fn, "the mask texture is not colour-renderable");
            return SK_ERR_GL;
        }
        e->fb_ok = 1;
    }
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, *w, *h);
    skgl__st_screen_pass(ctx, st);
    ctx->stage = "the mask pass";
    return SK_OK;
}

static void skgl__bind_unit(skgl__unitbind *b, int unit, int target, skgl__uint tex, skgl__uint sampler)
{
    b->unit = unit;
    b->target = target;
    b->tex = tex;
    b->sampler = sampler;
}

/* the G-buffer on units 1 (depth) and 2 (normals, when there are) through
   the point sampler: texelFetch reads them, and a sampler object of the
   caller's (comparison on, or a mipmapped filter without mipmaps) would
   make those reads undefined or 0; returns the binds written to b */
static int skgl__mask_gbuffer(const skgl_context *ctx, unsigned depth_tex, unsigned normal_tex, skgl__unitbind *b)
{
    skgl__bind_unit(&b[0], 1, SKGL__T_2D, depth_tex, ctx->point_sampler);
    /* WebGL2 refuses a draw when any sampler of the program, used or not,
       names a unit whose texture is attached to the framebuffer drawn to
       (a mask texture the caller left bound there): an unused unit gets
       no texture */
    if (!normal_tex && ctx->caps.webgl) { skgl__bind_unit(&b[1], 2, SKGL__T_2D, 0, 0); return 2; }
    if (!normal_tex) return 1;
    skgl__bind_unit(&b[1], 2, SKGL__T_2D, normal_tex, ctx->point_sampler);
    return 2;
}

/* the camera's matrices of a mask program: [0] inverse view-projection, [1] view */
static void skgl__mask_camera(skgl_context *ctx, skgl__int loc, const sk_mat4 *inv, const sk_mat4 *view)
{
    float m[32];
    memcpy(m, inv->m, sizeof inv->m);
    memcpy(m + 16, view->m, sizeof view->m);
    if (loc >= 0) ctx->gl.UniformMatrix4fv(loc, 2, 0, m);
}


/* ---- 6. Directional lights ---------------------------------------------- */
// >>shadow
/* a directional light; each technique's own state in its own part */
/* FERKO's part (Ferko 2013): the analysis at 1/4 of the G-buffer and its
   16x16 reductions (2-layer textures: bounds, patch; skgl__ferko_targets),
   the final 2x1 texel pair and its read-back ring; the G-buffer size they
   were made for; the estimate in use */
typedef struct skgl__ferko {
    skgl__uint tex[3], fbo[3], final, final_fbo;
    int lw[SKGL__FERKO_LEVELS], lh[SKGL__FERKO_LEVELS];   /* [0] the analysis, then the reductions */
    int w, h, levels;
    skgl__ring ring;
    int state;                     /* 0 no estimate yet, 1 an estimate */
    sk_mat4 lvp;                   /* the uncropped light frustum of the estimate */
    sk_res_estimate est;
    double origin[3];              /* the world point lvp is relative to */
    float depth_lo, depth_hi;      /* the view depths of the estimate's samples (0 0: none) */
} skgl__ferko;

/* RMSM's part (Romanick's VGP353 notes): the per-pixel samples (G-buffer
   size) and their framebuffer, the request atlas (R8) and the page table
   (RGBA8), atlas_w x atlas_h, the requests read back, the table as
   uploaded and as built, the pages of this frame and the pool slot of
   each, the virtual map's light frustum, the read-back ring; with
   desc.cache, what each slot holds */
typedef struct skgl__rmsm_slot {
    int level, px, py;             /* the page it holds */
    int valid;                     /* 1: its static casters' depth is that page's */
    int dyn;                       /* 1: the dynamic casters were drawn over it */
    unsigned last;                 /* the render that last used it (LRU) */
} skgl__rmsm_slot;

typedef struct skgl__lru {
    unsigned last;                 /* 0: an empty slot, taken first */
    int slot;
} skgl__lru;

typedef struct skgl__rmsm {
    skgl__uint samples, samples_fbo, requests, requests_fbo, table;
    int atlas_w, atlas_h, pages0, levels, w, h;
    int bands;                     /* request bands (rmsm_request.vert): 1 (rmsm_band_pages -1), else levels */
    int req_fmt;                   /* rmsm.requests' format: the atlas in R8, banded in RGBA8 */
    unsigned char *req_cpu, *table_cpu, *table_new;
    unsigned char *mark;           /* banded: per atlas texel, the band that last marked it (scratch) */
    int floor_level;               /* banded: the finest level this frame's band asks for (skgl__rmsm_bands) */
    sk_page *pages;
    int *slot_of;                  /* per page: its pool slot */
    int npages, analyzed;
    sk_mat4 lvp;
    skgl__ring ring;
    double origin[3];              /* the world point lvp is relative to */
    sk_aabb world;                 /* the scene's bounds (world) at the last render */
    skgl__uint page_tex, page_fbo; /* one slot of depth every page is drawn in (skgl__page_pass) */
    /* desc.layered: the batch target, SKGL_MAX_CASCADES slots of depth as
       the layers of an array texture (batch_fbo: all of them, layered;
       batch_layer_fbo[i]: layer i, to copy from), made on first use
       (batch_state 1; -1: not renderable or no layered program) */
    skgl__uint batch_tex, batch_fbo, batch_layer_fbo[SKGL_MAX_CASCADES];
    int batch_state;
    /* desc.cache: the slots, the slot + 1 of each atlas texel (0: not
       resident), the frame the slots were drawn for (key_lvp, key_origin),
       the render count; the static copy of the pool is cache.tex */
    skgl__rmsm_slot *slots;
    skgl__lru *lru;                /* the slots a frame may take, oldest first (scratch) */
    int *resident;
    sk_mat4 key_lvp;
    double key_origin[3];
    unsigned frame;
} skgl__rmsm;

/* the cache's part (CACHED MAPS, 6.5): the static casters' depth per
   cached layer and the world matrix its depth stands for (world: the one
   it was drawn with, moved by the whole texels it was scrolled); this
   frame's caster matrix of each layer (vp: world relative to the light's
   origin), what the cache did with it (how: 0 drawn whole, 1 scrolled by
   (sx, sy), 2 reused); whether the map's layer equals it; the boxes
   invalidated since the last render (all: every layer); the scratch map
   of .verify_cache */
typedef struct skgl__cache {
    skgl__uint tex, fbo[SKGL_MAX_CASCADES];
    int layers;
    int valid[SKGL_MAX_CASCADES], same[SKGL_MAX_CASCADES], dyn[SKGL_MAX_CASCADES][4];
    double world[SKGL_MAX_CASCADES][16];
    sk_mat4 vp[SKGL_MAX_CASCADES];
    int how[SKGL_MAX_CASCADES], sx[SKGL_MAX_CASCADES], sy[SKGL_MAX_CASCADES];
    sk_aabb dirty[SKGL_CACHE_REGIONS];
    int ndirty, all;
    skgl__uint verify_tex, verify_fbo;
} skgl__cache;

/* desc.filter = SKGL_FILTER_EVSM (FILTERABLE MAPS): the moments array (a
   bilinear RGBA32F layer per map, size x size texels), the horizontal
   pass's target (size x the map's side), and the framebuffers of both */
typedef struct skgl__evsm {
    skgl__uint tex, tmp, fbo[SKGL_MAX_CASCADES], tmp_fbo;
    int size;                      /* the moments' side: the map's, or fewer for a wide box (skgl__evsm_side) */
} skgl__evsm;

struct skgl_shadow {
    skgl_shadow_desc desc;
    unsigned id;                   /* per context, never reused: whose constants a program holds */
    skgl__uint tex;                /* GL_TEXTURE_2D_ARRAY of depth, one layer per map */
    skgl__uint fbo[SKGL_MAX_CASCADES];   /* one framebuffer per layer, checked when made */
    skgl__uint fbo_layered;              /* desc.layered: every layer at once (made on first use) */
    int layers;                    /* allocated */
    int maps;                      /* used by the last render (LSPSM: its partition count) */
    int tex_size;                  /* side of the texture (RMSM: the page pool) */
    float select_extent;           /* LSPSM: |light NDC| <= this selects a partition (its rect) */
    sk_mat4 vp[SKGL_MAX_CASCADES];          /* each layer's lookup matrix */
    sk_mat4 render_vp[SKGL_MAX_CASCADES];   /* the depth pass's matrix */
    int view_w, view_h;            /* viewport of every layer's depth pass */
    skgl__timer t_render, t_mask, t_analyze;
    double origin[3];              /* the world point vp and render_vp are relative to (they
                                      take p - origin; see skgl__origin) */
    sk_vec3 light_dir;             /* unit travel direction of the last render */
    int rendered;                  /* 1 after a render that succeeded: the maps may be read */
    skgl__ferko ferko;             /* SKGL_FERKO, SKGL_AUTO and .fit_to_depth */
    int auto_pick;                 /* SKGL_AUTO: the candidate in use (skgl__auto_pick; -1 before) */
    int auto_pick_analysed;        /* SKGL_AUTO: 1 when it was picked over an analysed range */
    int auto_maps_drawn;           /* SKGL_AUTO: the count of the last render (skgl__auto_storage) */
    sk_mat4 auto_view, auto_proj;  /* SKGL_AUTO: the camera of the last analysis run */
    int auto_kept;                 /* SKGL_AUTO: analyses kept (not run) since it ran */
    int tex_layers;                /* SKGL_AUTO: layers of s->tex (others: .layers) */
    int auto_sized;                /* SKGL_AUTO: 1 once a render sized s->tex to a count */
    int auto_settled;              /* SKGL_AUTO: renders at the count in use since it changed */
    int step[SKGL_MAX_CASCADES][2];   /* .stable: each crop's width and height, steps of the ladder
                                      2^(k/8) (skgl__ladder_step; SKGL__NO_STEP before the first) */
    int far_step;                  /* .stable: the shadow range's end, likewise */
    int step_below[SKGL_MAX_CASCADES][2], far_below;   /* .stable: renders in a row whose need was
                                      two steps below (skgl__ladder_step) */
    sk_mat4 step_view;             /* .stable: the camera of the last fit (skgl__camera_cut), */
    double step_eye[3];            /* its eye in world space */
    float fade_start;              /* the view depth where the distance fade starts (+INF: none) */
    skgl__rmsm rmsm;               /* SKGL_RMSM only */
    skgl__cache cache;             /* desc.cache only */
    skgl__evsm evsm;               /* desc.filter = SKGL_FILTER_EVSM only */
    skgl_shadow_frame_stats stats;
    /* skgl_shadow_contact_depth: the camera depth buffer of the forward
       contact march (0: none), its camera and depth convention */
    skgl__uint contact_tex;
    skgl_camera contact_cam;
    float contact_dmap[4];
};

/* what a fit starts from: the camera and the scene (relative to the
   light's origin), the light, the view frustum, its near and far planes
   and the far end of the shadows */
typedef struct skgl__fit_in {
    const skgl_camera *cam;
    const skgl_scene *scene;
    sk_vec3 light_dir;
    sk_mat4 lview;                 /* sk_light_view_directional(light_dir) */
    sk_frustum view;
    float zn, cam_zf, zf;
    float shadow_zn;               /* where the shadows start (zn, or later with .fit_to_depth) */
} skgl__fit_in;

// >>techniques
/* What differs from technique to technique, one row each in
   skgl_technique order: what its map is to the snippet and how many units
   a bind takes, its own objects, its analysis (skgl_shadow_analyze; NULL:
   none) and the light frustum the analysis projects into, the fit of its
   layers, its caster passes, and the textures of its own a bind and the
   mask add to the map's. */
typedef struct skgl__technique {
    const char *name;
    int analyses;                  /* 1: its analysis runs whatever the desc; 0: only with desc.fit_to_depth */
    int units;                     /* the units skgl_shadow_bind takes from `unit`: the map's, then its own */
    int pages;                     /* 1: the map is a page pool behind a page table (the snippet's sk_rmsm:
                                      a lookup spans the whole texture) */
    int select_by_map;             /* 1: the snippet picks a layer by the light NDC extent (sk_select_by_map) */
    sk_result (*create)(skgl_context *ctx, skgl__st *st, skgl_shadow *s);   /* NULL: nothing of its own */
    void (*destroy)(skgl_context *ctx, skgl_shadow *s);
    /* the analysis's light frustum relative to o (scene: world; rs: relative
       to o); NULL: skgl__ferko_light around rs */
    sk_result (*frame)(const skgl_scene *scene, const skgl_scene *rs, sk_vec3 light_dir, const double o[3],
                       sk_mat4 *lvp);
    sk_result (*analyze)(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_camera *cam, const sk_mat4 *inv,
                         const sk_mat4 *lvp, const double o[3], unsigned depth_tex, int w, int h);
    sk_result (*fit)(skgl_shadow *s, const skgl__fit_in *in);
    sk_result (*render)(skgl_context *ctx, skgl_shadow *s, const skgl_scene *scene, sk_vec3 light_dir);
    /* skgl_shadow_bind: its textures from unit + 1; the unit it left active (NULL: none) */
    skgl__int (*bind)(skgl_context *ctx, const skgl_shadow *s, int unit);
    /* skgl_shadow_mask: its textures (from unit 3) put in b; how many (NULL: none) */
    int (*mask)(const skgl_shadow *s, skgl__unitbind *b);
} skgl__technique;
static const skgl__technique *skgl__technique_of(const skgl_shadow *s);

/* defined in 6.3 and 6.4, used by the light's lifecycle and its fits */
#ifndef SKGL_NO_FERKO
static void skgl__ferko_free(skgl_context *ctx, skgl_shadow *s);
static void skgl__fit_ferko(skgl_shadow *s, float zf);
#endif
#ifndef SKGL_NO_RMSM
static sk_result skgl__rmsm_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s);
static void skgl__rmsm_free(skgl_context *ctx, skgl_shadow *s);
#endif
/* defined in 6.5 */
#ifndef SKGL_NO_CACHE
static sk_result skgl__cache_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s);
static void skgl__cache_free(skgl_context *ctx, skgl_shadow *s);
#endif
#if !defined(SKGL_NO_CACHE) || !defined(SKGL_NO_RMSM)
static sk_result skgl__verify_texture(skgl_context *ctx, skgl__st *st, skgl__uint *tex, skgl__uint *fbo, int w, int h,
                                      const char *fn);
#endif
/* defined in 6.6 (the filterable map) */
static sk_result skgl__evsm_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s);
static void skgl__evsm_free(skgl_context *ctx, skgl_shadow *s);
static void skgl__evsm_moments(skgl_context *ctx, skgl__st *st, skgl_shadow *s);

/* ---- 6.1 the light: its desc, create and destroy ---------------------- */
// >>shadow_life
/* the disable_ switches shared by directional and point lights (soft
   lights: the polygon offset's alone, plane_bias and pcf_radius NULL) */
static void skgl__apply_switches(float *slope_bias, float *depth_bias, int no_offset, float *plane_bias, int no_plane,
                                 int *pcf_radius, int no_kernel)
{
    if (no_offset) *slope_bias = *depth_bias = 0.0f;
    if (no_plane) *plane_bias = 0.0f;
    if (no_kernel) *pcf_radius = 0;
}

/* The ladder a stable crop's size and the stable shadow range's end step
   on: 2^(k/8), k an integer (9% steps, fixed in world units, so the same
   need gives the same size everywhere). The step for `need` (> 0): the
   smallest whose size holds it; `prev` (SKGL__NO_STEP: none) is kept while
   need fits it and is at most six steps (a factor 1.68) smaller, so that
   a need wavering about a step does not resize the crop back and forth.
   A need two or more steps below `prev` in SKGL__LADDER_SETTLE renders in
   a row (*below counts them) is no wavering: the crop shrinks to it, or a
   view that needed a large crop once would keep it for good. */
#define SKGL__NO_STEP (-100000)
#define SKGL__LADDER_SETTLE 60

/* whether stable crops step on the ladder (STABLE CROPS); a cached light
   keeps the sphere fit, whose crops never change size: a cached layer is
   drawn whole again whenever its crop's size changes */
static int skgl__stepped(const skgl_shadow_desc *d)
{
    return d->stable && !d->stable_sphere && !d->cache;
}
static double skgl__ladder(int k)
{
    static const double frac[8] = {1.0, 1.090507732665258, 1.189207115002721, 1.296839554651010,
                                   1.414213562373095, 1.542210825407941, 1.681792830507429, 1.834008086409342};
    return SK_LDEXP(frac[k & 7], k >> 3);   /* k >> 3 floors for negative k too (two's complement) */
}
static int skgl__ladder_step(double need, int prev, int *below)
{
    int e, k;
    if (!(need > 0.0) || !(need < 1e30)) return prev;
    SK_FREXP(need, &e);
    for (k = 8 * (e - 1); skgl__ladder(k) < need; k++) {}
    *below = prev != SKGL__NO_STEP && k <= prev - 2 ? *below + 1 : 0;
    if (prev != SKGL__NO_STEP && k <= prev && k >= prev - 6 && *below < SKGL__LADDER_SETTLE) return prev;
    *below = 0;
    return k;
}

/* A camera cut for the stepped crops: the camera turned more than about
   30 degrees (a rotation element changed by more than 0.5) or moved
   farther than the first crop's smaller side since the last render. The
   last view's needs say nothing about the new one's then: every step
   starts afresh (skgl__fit_layers), instead of the new view inheriting
   crops up to 1.68x too large (measured in the open world: stable cascades
   1.42-1.61x the focused ones' error after a cut, 1.00-1.10x afresh). */
/* the eye of cam (relative to s->origin) in world space */
static void skgl__world_eye(const skgl_shadow *s, const skgl_camera *cam, double eye[3])
{
    int k;
    skgl__view_eye(&cam->view, eye);
    for (k = 0; k < 3; k++) eye[k] += s->origin[k];
}

static int skgl__camera_cut(const skgl_shadow *s, const skgl_camera *cam)
{
    double eye[3], reach;
    if (s->step[0][0] == SKGL__NO_STEP || s->step[0][1] == SKGL__NO_STEP) return 0;
    if (skgl__view_turned(&cam->view, &s->step_view, 0.5f)) return 1;
    skgl__world_eye(s, cam, eye);
    reach = skgl__ladder(s->step[0][0] < s->step[0][1] ? s->step[0][0] : s->step[0][1]);
    return !(skgl__dist2(eye, s->step_eye) <= reach * reach);
}

static void skgl__settled_layer_steps(skgl_shadow *s)
{
    int i;
    for (i = 0; i < SKGL_MAX_CASCADES; i++) s->step_below[i][0] = s->step_below[i][1] = SKGL__LADDER_SETTLE;
}

static void skgl__restart_steps(skgl_shadow *s)
{
    int i;
    for (i = 0; i < SKGL_MAX_CASCADES; i++) {
        s->step[i][0] = s->step[i][1] = SKGL__NO_STEP;
        s->step_below[i][0] = s->step_below[i][1] = 0;
    }
    s->far_step = SKGL__NO_STEP;
    s->far_below = 0;
}

static skgl_shadow_desc skgl__defaults(const skgl_shadow_desc *d)
{
    skgl_shadow_desc r = *d;
    if (r.resolution == 0) r.resolution = r.technique == SKGL_RMSM ? 16384 : 2048;
    if (r.rmsm_page_size == 0) r.rmsm_page_size = 128;
    if (r.rmsm_pool_pages == 0) r.rmsm_pool_pages = 24;
    if (r.lspsm.zeta == 0.0f) r.lspsm.zeta = 0.25f;
    if (r.lspsm.sigma == 0.0f) r.lspsm.sigma = 0.5f;
    if (r.lspsm.h_max == 0) r.lspsm.h_max = 4;
    if (r.lspsm.nw_max == 0) r.lspsm.nw_max = 2;
    if (r.cascades == 0) r.cascades = r.technique == SKGL_LISPSM ? 1 : 4;
    /* LSPSM: one layer per possible partition; how many are used is per frame */
    if (r.technique == SKGL_LSPSM && r.lspsm.h_max > 0 && r.lspsm.nw_max > 0 &&
        r.lspsm.h_max <= SKGL_MAX_CASCADES && r.lspsm.nw_max <= SKGL_MAX_CASCADES)
        r.cascades = r.lspsm.h_max * r.lspsm.nw_max;
    if (r.technique == SKGL_STANDARD || r.technique == SKGL_PSM || r.technique == SKGL_FERKO ||
        r.technique == SKGL_RMSM)
        r.cascades = 1;
    /* a disable_ switch wins over its value, which then reads 0 (none): the
       filled desc given back to skgl_shadow_create makes the same light */
    if (r.uniform_splits) r.lambda = 0.0f;
    else if (r.lambda == 0.0f && !(r.fit_to_depth && r.technique != SKGL_AUTO)) r.lambda = 0.75f;
    if (r.slope_bias == 0.0f) r.slope_bias = 2.0f;
    if (r.depth_bias == 0.0f) r.depth_bias = 1.0f;
    if (r.normal_bias == 0.0f && r.bias == SKGL_BIAS_NORMAL_OFFSET) r.normal_bias = 1.5f;
    if (r.plane_bias == 0.0f) r.plane_bias = 0.5f;
    if (r.psm_slide == 0.0f) r.psm_slide = 0.5f;
    if (r.auto_texel_px == 0.0f) r.auto_texel_px = 1.0f;
    if (r.contact_steps == 0) r.contact_steps = 8;
    if (r.contact_thickness == 0.0f) r.contact_thickness = r.contact_length;
    if (r.fade_band == 0.0f) r.fade_band = 0.1f;
    if (r.disable_fade) r.fade_band = 0.0f;
    if (r.pcf_radius == 0) r.pcf_radius = 1;
    if (r.bias == SKGL_BIAS_NONE) r.normal_bias = 0.0f;
    skgl__apply_switches(&r.slope_bias, &r.depth_bias, r.disable_polygon_offset, &r.plane_bias,
                         r.disable_plane_bias, &r.pcf_radius, r.disable_pcf_kernel);
    if (r.disable_pcf_kernel) r.filter_world = 0.0f;
    if (r.disable_psm_slide) r.psm_slide = 0.0f;
    if (r.evsm_blur == 0) r.evsm_blur = 2;
    if (r.disable_evsm_blur) r.evsm_blur = 0;
    return r;
}

/* the texels the PCF box reaches beyond its point: .pcf_radius, or with a
   world radius the most the shader takes (SK_PCF_MAX_TEXELS in
   shadow_sample.glsl), whatever the layer's texel size */
static int skgl__filter_reach(const skgl_shadow_desc *d)
{
    return d->filter_world > 0.0f ? 8 : d->pcf_radius;
}

/* hand-set splits: all 0, or one finite increasing depth > 0 per boundary
   between the cascades and none past them */
static sk_result skgl__split_rules(skgl_context *ctx, const char *fn, const skgl_shadow_desc *d)
{
    int i, given = 0, n = d->cascades > 1 ? d->cascades - 1 : 0;
    for (i = 0; i < SKGL_MAX_CASCADES - 1; i++) given |= d->splits[i] != 0.0f;
    if (!given) return SK_OK;
    if (d->technique != SKGL_PSSM && d->technique != SKGL_LISPSM)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.splits is set: only SKGL_PSSM and SKGL_LISPSM have "
                                                   "cascades to split", fn);
    if (d->uniform_splits)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.splits and desc.uniform_splits are both set", fn);
    for (i = 0; i < SKGL_MAX_CASCADES - 1; i++) {
        float v = d->splits[i];
        if (i >= n && v != 0.0f)
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.splits[%d] = %g: %d cascades have %d boundaries "
                                                       "(the rest 0)", fn, i, (double)v, d->cascades, n);
        if (i < n && !(v > 0.0f && v < 1e30f))
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.splits[%d] = %g: a finite view depth more than 0",
                              fn, i, (double)v);
        if (i > 0 && i < n && !(v > d->splits[i - 1]))
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.splits[%d] = %g: more than desc.splits[%d] = %g",
                              fn, i, (double)v, i - 1, (double)d->splits[i - 1]);
    }
    return SK_OK;
}

/* The layers' view depths this frame: zn, the boundaries, zf. Hand-set
   boundaries are kept inside (zn, zf), each a little past the one before
   (a relative step of 1e-4), so no cascade is empty. */
static sk_result skgl__splits(const skgl_shadow_desc *d, float lambda, int layers, float zn, float zf, float *out)
{
    int i;
    if (layers == 1) { out[0] = zn; out[1] = zf; return SK_OK; }
    if (d->splits[0] == 0.0f) return sk_pssm_splits(zn, zf, layers, lambda, out);
    out[0] = zn;
    out[layers] = zf;
    for (i = 1; i < layers; i++) {
        float lo = out[i - 1] * (1.0f + 1e-4f), hi = zf * (1.0f - 1e-4f * (float)(layers - i));
        float v = d->splits[i - 1];
        out[i] = v > hi ? hi : v;
        if (out[i] < lo) out[i] = lo;
    }
    return SK_OK;
}

/* desc.filter and the EVSM fields: the moments are RGBA32F targets, read
   through bilinear filtering */
static sk_result skgl__evsm_rules(skgl_context *ctx, const char *fn, const skgl_shadow_desc *d)
{
    int evsm = d->filter == SKGL_FILTER_EVSM;
    SKGL__RULE(d->filter == SKGL_FILTER_PCF || evsm, fn, "filter", d->filter,
               "SKGL_FILTER_PCF (0) or SKGL_FILTER_EVSM (1)");
    SKGL__RULE(!evsm || d->technique != SKGL_RMSM, fn, "filter", d->filter,
               "SKGL_FILTER_EVSM blurs whole maps: not with SKGL_RMSM (a pool of pages of many levels)");
    SKGL__RULE(d->disable_evsm_blur == 0 || d->disable_evsm_blur == 1, fn, "disable_evsm_blur", d->disable_evsm_blur,
               "0 or 1");
    SKGL__RULE(d->disable_evsm_blur || (d->evsm_blur >= 1 && d->evsm_blur <= 64), fn, "evsm_blur", d->evsm_blur,
               "in 1..64 texels (0: the default 2; disable_evsm_blur for none)");
    SKGL__RULE(d->evsm_bleed >= 0.0f && d->evsm_bleed < 1.0f, fn, "evsm_bleed", d->evsm_bleed, "in [0, 1)");
    SKGL__NEED(!evsm || ctx->caps.float_render, fn, "SKGL_FILTER_EVSM's moments", SKGL__FLOAT_RENDER);
    /* OpenGL ES 3.0 filters 32-bit float textures only with this extension
       (an unfilterable texture under GL_LINEAR is incomplete: it reads 0) */
    SKGL__NEED(!evsm || ctx->caps.api == SKGL_API_GL33 || skgl__has_extension(ctx, "GL_OES_texture_float_linear"), fn,
               "SKGL_FILTER_EVSM's moments", "linear filtering of 32-bit float textures (GL_OES_texture_float_linear "
               "on OpenGL ES and WebGL2)");
    return SK_OK;
}

/* every rule of a skgl_shadow_desc (defaults filled), in field order */
static sk_result skgl__shadow_validate(skgl_context *ctx, const skgl_shadow_desc *d)
{
    const char *fn = "skgl_shadow_create";
    int lspsm = d->technique == SKGL_LSPSM, rmsm = d->technique == SKGL_RMSM;
    SKGL__RULE((int)d->technique >= (int)SKGL_STANDARD && (int)d->technique <= (int)SKGL_AUTO, fn, "technique",
               d->technique, "one of skgl_technique");
#ifdef SKGL_NO_FERKO
    SKGL__RULE(d->technique != SKGL_FERKO, fn, "technique", d->technique,
               "FERKO's resolution estimation is compiled out (SKGL_NO_FERKO)");
    SKGL__RULE(d->technique != SKGL_AUTO, fn, "technique", d->technique,
               "AUTO splits the depth range of the depth analysis, which is compiled out (SKGL_NO_FERKO)");
#endif
    SKGL__RULE(d->resolution >= 1, fn, "resolution", d->resolution, "1 or more (0: the default)");
    SKGL__RULE(rmsm || d->resolution <= 16384, fn, "resolution", d->resolution, "at most 16384");
    /* a stable crop snaps to whole texels of a map of at least two */
    SKGL__RULE(!d->stable || d->resolution >= 2, fn, "resolution", d->resolution, "2 or more with desc.stable");
    SKGL__RULE(d->stable == 0 || d->stable == 1, fn, "stable", d->stable, "0 or 1");
    SKGL__RULE(d->stable_sphere == 0 || (d->stable_sphere == 1 && d->stable), fn, "stable_sphere", d->stable_sphere,
               "0, or 1 with desc.stable");
    /* LSPSM's layers are h_max * nw_max (the defaults set .cascades to it):
       that rule first, so that the message names the fields the caller set */
    /* (in double: two large ints' product would overflow) */
    SKGL__RULE(!lspsm || (double)d->lspsm.h_max * (double)d->lspsm.nw_max <= SKGL_MAX_CASCADES, fn,
               "lspsm.h_max * lspsm.nw_max", (double)d->lspsm.h_max * (double)d->lspsm.nw_max,
               "at most SKGL_MAX_CASCADES");
    SKGL__RULE(d->cascades >= 1 && d->cascades <= SKGL_MAX_CASCADES, fn, "cascades", d->cascades,
               "in 1..SKGL_MAX_CASCADES (8; 0: the default)");
    SKGL__RULE(d->lambda >= 0.0f && d->lambda <= 1.0f, fn, "lambda", d->lambda, "in (0, 1] (uniform_splits for 0)");
    SKGL__TRY(skgl__split_rules(ctx, fn, d));
    SKGL__RULE(d->blend_band >= 0.0f && d->blend_band < 1.0f, fn, "blend_band", d->blend_band, "in [0, 1)");
    SKGL__TRY(skgl__bias_rules(ctx, fn, d->slope_bias, d->depth_bias, d->normal_bias, d->bias, d->plane_bias,
                               d->pcf_radius));
    SKGL__RULE(d->filter_world >= 0.0f && d->filter_world <= 1e6f, fn, "filter_world", d->filter_world,
               "in [0, 1000000] world units (0: pcf_radius texels)");
    SKGL__RULE(d->max_distance >= 0.0f, fn, "max_distance", d->max_distance, "0 or more");
    SKGL__RULE(d->disable_fade == 0 || d->disable_fade == 1, fn, "disable_fade", d->disable_fade, "0 or 1");
    SKGL__RULE(d->disable_fade || (d->fade_band > 0.0f && d->fade_band <= 1.0f), fn, "fade_band", d->fade_band,
               "in (0, 1] (disable_fade for none)");
    SKGL__RULE(d->psm_slide >= 0.0f && d->psm_slide <= 1e3f, fn, "psm_slide", d->psm_slide,
               "in [0, 1000] (disable_psm_slide for none)");
    SKGL__RULE(d->layered == 0 || d->layered == 1, fn, "layered", d->layered, "0 or 1");
    SKGL__RULE(d->contact_length >= 0.0f && d->contact_length <= 1e6f, fn, "contact_length", d->contact_length,
               "finite, 0 or more (0: no contact shadows)");
    SKGL__RULE(d->contact_steps >= 1 && d->contact_steps <= 64, fn, "contact_steps", d->contact_steps, "in 1..64");
    SKGL__RULE(d->contact_length == 0.0f || (d->contact_thickness > 0.0f && d->contact_thickness <= 1e6f), fn,
               "contact_thickness", d->contact_thickness, "finite, more than 0");
    SKGL__NEED(!d->layered || ctx->caps.geometry_shader, fn, "desc.layered", SKGL__GEOMETRY);
    SKGL__NEED(ctx->caps.float_render || (d->technique != SKGL_FERKO && d->technique != SKGL_RMSM), fn,
               d->technique == SKGL_FERKO ? "SKGL_FERKO's analysis" : "SKGL_RMSM's page requests",
               SKGL__FLOAT_RENDER);
    SKGL__NEED(ctx->caps.float_render || (d->technique != SKGL_AUTO && !d->fit_to_depth), fn,
               d->technique == SKGL_AUTO ? "SKGL_AUTO's analysis" : "desc.fit_to_depth's analysis",
               SKGL__FLOAT_RENDER);
    SKGL__NEED(ctx->caps.float_blend || d->technique != SKGL_RMSM, fn, "SKGL_RMSM's page requests",
               SKGL__FLOAT_BLEND);
    SKGL__RULE(d->lspsm.zeta > 0.0f && d->lspsm.zeta < 0.5f, fn, "lspsm.zeta", d->lspsm.zeta, "in (0, 0.5)");
    SKGL__RULE(d->lspsm.sigma > 0.0f && d->lspsm.sigma <= 1e3f, fn, "lspsm.sigma", d->lspsm.sigma, "in (0, 1000]");
    SKGL__RULE(d->lspsm.h_max >= 1 && (!lspsm || d->lspsm.h_max <= SKGL_MAX_CASCADES), fn, "lspsm.h_max",
               d->lspsm.h_max, "in 1..SKGL_MAX_CASCADES");
    SKGL__RULE(d->lspsm.nw_max >= 1 && (!lspsm || d->lspsm.nw_max <= SKGL_MAX_CASCADES), fn, "lspsm.nw_max",
               d->lspsm.nw_max, "in 1..SKGL_MAX_CASCADES");
    SKGL__RULE(d->sync_readback == 0 || d->sync_readback == 1, fn, "sync_readback", d->sync_readback, "0 or 1");
    SKGL__RULE(d->cache == 0 || d->cache == 1, fn, "cache", d->cache, "0 or 1");
#ifdef SKGL_NO_CACHE
    SKGL__RULE(!d->cache, fn, "cache", d->cache, "cached maps are compiled out (SKGL_NO_CACHE)");
#endif
    SKGL__RULE(d->fit_to_depth == 0 || d->fit_to_depth == 1, fn, "fit_to_depth", d->fit_to_depth, "0 or 1");
#ifdef SKGL_NO_FERKO
    SKGL__RULE(!d->fit_to_depth, fn, "fit_to_depth", d->fit_to_depth,
               "the depth analysis is compiled out (SKGL_NO_FERKO)");
#endif
    SKGL__RULE(d->auto_texel_px > 0.0f && d->auto_texel_px <= 1e6f, fn, "auto_texel_px", d->auto_texel_px,
               "in (0, 1e6] (0: the default 1)");
    SKGL__RULE(d->disable_auto_warp == 0 || d->disable_auto_warp == 1, fn, "disable_auto_warp", d->disable_auto_warp,
               "0 or 1");
    SKGL__RULE(!d->fit_to_depth || d->technique == SKGL_STANDARD || d->technique == SKGL_PSSM ||
                   d->technique == SKGL_LISPSM || d->technique == SKGL_AUTO,
               fn, "fit_to_depth", d->fit_to_depth, "STANDARD, PSSM or LiSPSM (AUTO always fits)");
    /* a range that follows the depth buffer moves the splits every frame */
    SKGL__RULE(!d->stable || (!d->fit_to_depth && d->technique != SKGL_AUTO), fn, "stable", d->stable,
               "0 with desc.fit_to_depth and SKGL_AUTO (their splits follow the depth buffer)");
    SKGL__RULE(!d->cache || (!d->fit_to_depth && d->technique != SKGL_AUTO), fn, "cache", d->cache,
               "0 with desc.fit_to_depth and SKGL_AUTO (their splits follow the depth buffer)");
    SKGL__RULE(!d->cache || d->technique != SKGL_FERKO, fn, "cache", d->cache,
               "FERKO's crop and size follow the G-buffer every frame: STANDARD, PSSM, PSM, LiSPSM, LSPSM or RMSM");
    SKGL__RULE(!d->cache || !d->layered, fn, "cache", d->cache,
               "a cached light draws its static and dynamic casters a pass per layer: not with desc.layered");
    SKGL__RULE(d->cache_budget_kb >= 0, fn, "cache_budget_kb", d->cache_budget_kb, "0 (no limit) or more");
    SKGL__RULE(d->verify_cache == 0 || (d->verify_cache == 1 && d->cache), fn, "verify_cache", d->verify_cache,
               "0, or 1 with desc.cache");
    SKGL__NEED(!d->verify_cache || ctx->caps.api == SKGL_API_GL33, fn, "desc.verify_cache",
               "depth read-backs (glReadPixels of GL_DEPTH_COMPONENT: desktop OpenGL)");
    SKGL__TRY(skgl__evsm_rules(ctx, fn, d));
    if (!rmsm) return SK_OK;
#ifdef SKGL_NO_RMSM
    SKGL__RULE(0, fn, "technique", d->technique, "RMSM is compiled out (SKGL_NO_RMSM)");
#endif
    SKGL__RULE(d->rmsm_page_size >= 16 && d->rmsm_page_size <= 1024 && !(d->rmsm_page_size & (d->rmsm_page_size - 1)),
               fn, "rmsm_page_size", d->rmsm_page_size, "a power of two in 16..1024");
    SKGL__RULE(d->resolution >= d->rmsm_page_size && !(d->resolution & (d->resolution - 1)) &&
                   d->resolution / d->rmsm_page_size <= 1024,
               fn, "resolution", d->resolution, "RMSM: a power of two, rmsm_page_size to 1024 pages");
    SKGL__RULE(d->rmsm_pool_pages >= 2 && d->rmsm_pool_pages <= 64 && d->rmsm_pool_pages * (d->rmsm_page_size + 2) <= 16384,
               fn, "rmsm_pool_pages", d->rmsm_pool_pages, "in 2..64, rmsm_pool_pages * (rmsm_page_size + 2) <= 16384");
    SKGL__RULE(d->rmsm_band_pages >= -1 && d->rmsm_band_pages <= d->rmsm_pool_pages * d->rmsm_pool_pages, fn,
               "rmsm_band_pages", d->rmsm_band_pages, "-1 (none), 0 (the default) or up to rmsm_pool_pages^2");
    return SK_OK;
}

SKGLDEF sk_result skgl_shadow_create(skgl_context *ctx, const skgl_shadow_desc *desc, skgl_shadow **out)
{
    static const char fn[] = "skgl_shadow_create";
    skgl_shadow *s;
    skgl__st st;
    skgl__api *gl;
    skgl_shadow_desc d;
    sk_result r;
    int i;
    if (out) *out = NULL;
    SKGL__TRY(skgl__create_open(ctx, fn, !desc, !out));
    d = skgl__defaults(desc);
    r = skgl__shadow_validate(ctx, &d);
    if (r != SK_OK) return r;
    s = (skgl_shadow *)skgl__create_alloc(ctx, fn, sizeof *s);
    if (!s) return SK_ERR_CAPACITY;
    s->desc = d;
    s->id = ++ctx->next_id;
    if (!s->id) s->id = ++ctx->next_id;
    s->layers = d.cascades;
    s->maps = s->layers;
    s->tex_size = skgl__technique_of(s)->pages ? d.rmsm_pool_pages * (d.rmsm_page_size + 2) : d.resolution;
    /* AUTO: one layer, its one-map size, until a render sizes it (skgl__auto_storage) */
    s->tex_layers = d.technique == SKGL_AUTO ? 1 : s->layers;
    s->select_extent = 1.0f;
    s->auto_pick = -1;
    skgl__restart_steps(s);
    s->fade_start = SK__INF;
    gl = &ctx->gl;
    skgl__st_begin(ctx, &st);
    skgl__timer_init(ctx, &s->t_render);
    skgl__timer_init(ctx, &s->t_mask);
    skgl__timer_init(ctx, &s->t_analyze);
    gl->GenTextures(1, &s->tex);
    ctx->objects++;
    skgl__st_unpack(ctx, &st);
    skgl__st_set1(ctx, &st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY), (skgl__int)s->tex);
    skgl__st_unit(ctx, &st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    gl->TexImage3D(SKGL__TEXTURE_2D_ARRAY, 0, SKGL__DEPTH_COMPONENT32F, s->tex_size, s->tex_size, s->tex_layers, 0,
                   SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MIN_FILTER, SKGL__LINEAR);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MAG_FILTER, SKGL__LINEAR);
    /* one framebuffer per layer (a page pool: layer 0) */
    for (i = 0; i < (skgl__technique_of(s)->pages ? 1 : s->tex_layers) && r == SK_OK; i++) {
        s->fbo[i] = skgl__framebuffer(ctx, &st, 0, 0, s->tex, i);
        if (!s->fbo[i]) {
            skgl__set_log(ctx, "skgl_shadow_create: shadow framebuffer incomplete", NULL);
            r = SK_ERR_GL;
        }
    }
    if (r == SK_OK && skgl__technique_of(s)->create) r = skgl__technique_of(s)->create(ctx, &st, s);
#ifndef SKGL_NO_CACHE
    /* a page pool caches its pages itself (skgl__rmsm_create) */
    if (r == SK_OK && d.cache && !skgl__technique_of(s)->pages) r = skgl__cache_create(ctx, &st, s);
#endif
    if (r == SK_OK && d.filter == SKGL_FILTER_EVSM) r = skgl__evsm_create(ctx, &st, s);
    skgl__st_end(ctx, &st);
    r = skgl__create_close(ctx, fn, r, "the light's depth texture and framebuffers (out of GPU "
                           "memory, or desc.resolution above GL_MAX_TEXTURE_SIZE?)");
    if (r != SK_OK) {
        skgl_shadow_destroy(ctx, s);
        return r;
    }
    s->stats.shadow_ms = s->stats.mask_ms = s->stats.analysis_ms = -1.0f;
    *out = s;
    return SK_OK;
}

/* everything the light holds but the struct itself */
static void skgl__shadow_free(skgl_context *ctx, skgl_shadow *s)
{
    int i;
    skgl__delete_texture(ctx, &s->tex);
    for (i = 0; i < SKGL_MAX_CASCADES; i++) skgl__delete_framebuffer(ctx, &s->fbo[i]);
    skgl__delete_framebuffer(ctx, &s->fbo_layered);
#ifndef SKGL_NO_CACHE
    skgl__cache_free(ctx, s);
#endif
    skgl__evsm_free(ctx, s);
    if (skgl__technique_of(s)->destroy) skgl__technique_of(s)->destroy(ctx, s);
    skgl__timer_free(ctx, &s->t_render);
    skgl__timer_free(ctx, &s->t_mask);
    skgl__timer_free(ctx, &s->t_analyze);
}
SKGLDEF void skgl_shadow_destroy(skgl_context *ctx, skgl_shadow *s)
{
    if (!ctx || !s) return;
    skgl__shadow_free(ctx, s);
    SKGL_FREE(s);
}
SKGLDEF skgl_shadow_desc skgl_shadow_get_desc(const skgl_shadow *s)
{
    skgl_shadow_desc d;
    if (s) return s->desc;
    memset(&d, 0, sizeof d);
    return d;
}
SKGLDEF const skgl_shadow_frame_stats *skgl_shadow_stats(const skgl_shadow *s) { return s ? &s->stats : NULL; }

SKGLDEF sk_mat4 skgl_shadow_matrix(const skgl_shadow *s, int layer)
{
    if (!s || layer < 0 || layer >= s->layers) return sk_mat4_identity();
    return skgl__shift(&s->vp[layer], s->origin, skgl__zero3);
}
SKGLDEF float skgl_shadow_select_extent(const skgl_shadow *s) { return s ? s->select_extent : 1.0f; }
SKGLDEF unsigned skgl_shadow_texture(const skgl_shadow *s) { return s ? s->tex : 0; }
SKGLDEF unsigned skgl_shadow_analysis_texture(const skgl_shadow *s) { return s ? s->rmsm.samples : 0; }
SKGLDEF int skgl_shadow_pages(const skgl_shadow *s, sk_page *out, int cap)
{
    int i;
    if (!s) return 0;
    for (i = 0; out && i < s->rmsm.npages && i < cap; i++) out[i] = s->rmsm.pages[i];
    return s->rmsm.npages;
}

/* ---- 6.2 fits: the layers' crops and warps ---------------------------- */
// >>fits
/* near and far of a perspective (or orthographic) GL projection */
static int skgl__near_far(const sk_mat4 *p, float *zn, float *zf)
{
    double a = p->m[10], b = p->m[14], n, f;
    if (p->m[11] == -1.0f && p->m[15] == 0.0f) { n = b / (a - 1.0); f = b / (a + 1.0); }
    else if (p->m[11] == 0.0f && p->m[15] == 1.0f && a != 0.0) { n = (b + 1.0) / a; f = (b - 1.0) / a; }
    else return 0;
    *zn = (float)n; *zf = (float)f;
    return sk__finite(*zn) && sk__finite(*zf) && *zf > *zn && (p->m[11] == 0.0f || *zn > 0.0f);
}

/* The part of a view slice that can hold receivers: the slice clipped to
   the scene bounds (its corners when the clip is empty), and its range of
   eye depths. Returns the point count. */
static int skgl__receiver_body(const sk_frustum *slice, const skgl_scene *scene, const sk_mat4 *cam_view,
                               sk_vec3 *pts, float *dmin, float *dmax)
{
    int i, n = sk_clip_frustum_aabb(slice, scene->bounds, pts, SK_CLIP_MAX_POINTS);
    if (n <= 0) {
        for (i = 0; i < 8; i++) pts[i] = slice->corners[i];
        n = 8;
    }
    *dmin = SK__INF;
    *dmax = -SK__INF;
    for (i = 0; i < n; i++) {
        float z = -sk__xform_affine(cam_view, pts[i]).z;
        if (z < *dmin) *dmin = z;
        if (z > *dmax) *dmax = z;
    }
    return n;
}

/* The casters that can shadow the receiver body, as the vertices of their
   convex hull: each body point and where its ray toward the light leaves
   the scene bounds (the light-space hull of the receivers and their
   casters, Stamminger and Drettakis 2002, Sec. 4). A caster outside the
   hull shadows nothing the view can see. Each vertex goes out as a box of
   zero size, because PSM needs the hull itself, not a box around it: in
   post-perspective space every hull point lies between its receiver and
   the light, whereas a box's far corners can lie beyond the light, where
   no perspective frustum from the light holds them (a low sun from the
   side), and the whole scene box puts casters a kilometre behind the
   camera (the virtual camera slid back that far: a uniform map). Returns
   the box count, 2 n. */
static int skgl__caster_hull(const sk_vec3 *body, int n, sk_vec3 light_dir, const sk_aabb *bounds, sk_aabb *out)
{
    const float lo[3] = {bounds->min.x, bounds->min.y, bounds->min.z};
    const float hi[3] = {bounds->max.x, bounds->max.y, bounds->max.z};
    const float dir[3] = {-light_dir.x, -light_dir.y, -light_dir.z};
    int i, k;
    for (i = 0; i < n; i++) {
        const float p[3] = {body[i].x, body[i].y, body[i].z};
        float q[3];
        double t = 1e30;
        for (k = 0; k < 3; k++) {
            double e = dir[k] > 0.0f ? (hi[k] - p[k]) / dir[k] : dir[k] < 0.0f ? (lo[k] - p[k]) / dir[k] : 1e30;
            if (e < t) t = e;
        }
        if (!(t > 0.0 && t < 1e30)) t = 0.0;
        for (k = 0; k < 3; k++) q[k] = (float)(p[k] + t * dir[k]);
        out[2 * i].min = out[2 * i].max = body[i];
        out[2 * i + 1].min = out[2 * i + 1].max = sk__v3(q[0], q[1], q[2]);
    }
    return 2 * n;
}

/* Light-space perspective shadow map of one slice (Wimmer et al. 2004, the
   LiSPSM): the slice's receiver body, n_opt from the nearest
   receiver depth of the slice. */
static sk_result skgl__lispsm_warp(const skgl_camera *cam, const skgl_scene *scene, sk_vec3 light_dir,
                                   const sk_frustum *slice, float z0, sk_lispsm_result *lr)
{
    sk_vec3 body[SK_CLIP_MAX_POINTS];
    sk_mat4 inv;
    sk_lispsm_desc ld;
    float dmin, dmax;
    memset(&ld, 0, sizeof ld);
    ld.body_count = skgl__receiver_body(slice, scene, &cam->view, body, &dmin, &dmax);
    if (!sk_mat4_inverse(cam->view, &inv)) return SK_ERR_INVALID_ARG;
    ld.eye = sk__v3(inv.m[12], inv.m[13], inv.m[14]);
    ld.view_dir = sk__v3(-cam->view.m[2], -cam->view.m[6], -cam->view.m[10]);
    ld.zn = dmin > z0 ? dmin : z0;
    ld.light_dir = light_dir;
    ld.body = body;
    ld.casters = &scene->bounds;
    return sk_lispsm_matrices(&ld, lr);
}

static sk_result skgl__fit_lispsm(skgl_shadow *s, int layer, const skgl_camera *cam, const skgl_scene *scene,
                                  sk_vec3 light_dir, const sk_frustum *slice, float z0)
{
    sk_lispsm_result lr;
    sk_result r = skgl__lispsm_warp(cam, scene, light_dir, slice, z0, &lr);
    if (r != SK_OK) return r;
    s->vp[layer] = lr.light_view_proj;
    s->stats.warp_n[layer] = lr.n;
    s->stats.warped[layer] = lr.warped;
    return SK_OK;
}

/* Perspective shadow map (Stamminger & Drettakis 2002) over the
   view range that holds receivers: the camera's near plane moved up to the
   nearest receiver (PSM's resolution depends on the near/far ratio). A light
   behind the viewer reverses the depth order (sk_psm_result.compare): the
   map's z is negated so the depth test and comparison stay LESS/LEQUAL. */
static sk_result skgl__fit_psm(skgl_shadow *s, const skgl_camera *cam, const skgl_scene *scene,
                               sk_vec3 light_dir, const sk_frustum *view, float zn, float cam_zf, float zf)
{
    sk_vec3 body[SK_CLIP_MAX_POINTS];
    sk_frustum slice;
    sk_psm_desc pd;
    sk_psm_result pr;
    sk_aabb casters[2 * SK_CLIP_MAX_POINTS];
    float dmin, dmax;
    sk_result r = sk_frustum_slice(view, zn, cam_zf, zn, zf, &slice);
    if (r != SK_OK) return r;
    memset(&pd, 0, sizeof pd);
    pd.body_count = skgl__receiver_body(&slice, scene, &cam->view, body, &dmin, &dmax);
    pd.body = body;
    pd.cam_view = cam->view;
    pd.fovy = (float)(2.0 * SK_ATAN(1.0 / cam->proj.m[5]));
    pd.aspect = cam->proj.m[5] / cam->proj.m[0];
    pd.zn = dmin > zn ? dmin * 0.999f : zn;
    pd.zf = dmax < zf ? dmax * 1.001f : zf;
    if (!(pd.zf > pd.zn)) pd.zf = pd.zn * 1.001f;
    pd.light_dir = light_dir;
    pd.caster_count = skgl__caster_hull(body, pd.body_count, light_dir, &scene->bounds, casters);
    pd.casters = casters;
    if (s->desc.psm_slide > 0.0f) pd.extra_slide = s->desc.psm_slide * (float)SK_SQRT((double)pd.zn * pd.zf);
    r = sk_psm_matrices(&pd, &pr);
    if (r != SK_OK) return r;
    if (pr.compare == SK_DEPTH_GREATER) {
        int c;
        for (c = 0; c < 4; c++) pr.light_view_proj.m[c * 4 + 2] = -pr.light_view_proj.m[c * 4 + 2];
    }
    s->vp[0] = pr.light_view_proj;
    s->stats.splits[0] = pd.zn;
    s->stats.splits[1] = pd.zf;
    s->stats.warped[0] = !pr.orthographic;
    s->stats.depth_reversed = pr.compare == SK_DEPTH_GREATER;
    s->stats.psm_slide = pr.slide;
    return SK_OK;
}

/* Light Space Partitioned Shadow Maps (Tang et al. 2017): the trapezoid around the
   refined view frustum on the light plane, its partitions (Eq. 1), one
   orthographic crop each, every crop widened by a margin of texels so the
   PCF kernel and the normal offset of a point near a partition's edge stay
   inside that partition's map. The shader picks the partition whose rect
   holds the point (|NDC| <= select_extent). View direction along the light
   (no trapezoid axis): the region's documented fallback, one focused map. */
static sk_result skgl__fit_lspsm(skgl_shadow *s, const skgl_camera *cam, const skgl_scene *scene,
                                 sk_vec3 light_dir, const sk_frustum *view, float zn, float cam_zf, float zf)
{
    sk_frustum slice;
    sk_lspsm_region reg;
    sk_vec3 view_dir = sk__v3(-cam->view.m[2], -cam->view.m[6], -cam->view.m[10]);
    float margin = (float)(skgl__filter_reach(&s->desc) + 3) + (s->desc.normal_bias > 0.0f ? s->desc.normal_bias : 0.0f);
    float k = 1.0f - 2.0f * margin / (float)s->desc.resolution;
    int i, n;
    sk_result r = sk_frustum_slice(view, zn, cam_zf, zn, zf, &slice);
    if (r != SK_OK) return r;
    s->stats.splits[0] = zn;
    s->stats.splits[1] = zf;
    if (!(k > 0.5f)) k = 0.5f;
    r = sk_lspsm_region_extract(&slice, view_dir, scene->bounds, &scene->bounds, light_dir, &reg);
    if (r == SK_ERR_DEGENERATE) {
        /* the view holds no receiver: one map over the slice, nothing to see */
        sk_mat4 lview = sk_light_view_directional(light_dir), proj;
        r = sk_fit_ortho(slice.corners, 8, lview, &scene->bounds, &proj);
        if (r != SK_OK) return r;
        s->vp[0] = sk_mat4_mul(proj, lview);
        s->maps = 1;
        s->stats.lspsm_fallback = 1;
        s->select_extent = 1.0f;
        return SK_OK;
    }
    if (r != SK_OK) return r;
    n = sk_lspsm_crops(&reg, &s->desc.lspsm, s->vp, NULL, s->layers);
    if (n <= 0) return n < 0 ? (sk_result)-n : SK_ERR_DEGENERATE;
    for (i = 0; i < n; i++) {
        int c;
        for (c = 0; c < 4; c++) { s->vp[i].m[c * 4] *= k; s->vp[i].m[c * 4 + 1] *= k; }
    }
    s->maps = n;
    s->stats.lspsm_fallback = reg.fallback;
    s->select_extent = k;
    return SK_OK;
}

/* .fit_to_depth, SKGL_AUTO: the shadow range [*zn, *zf] narrowed to the
   view depths the analysis found (sample distribution shadow maps,
   Lauritzen, Salvi and Lefohn 2011), widened by a margin: float rounding
   for this frame's range (.sync_readback), 10% for an earlier frame's,
   which a camera moving at a tenth of the nearest depth per frame still
   stays inside. Nothing changes before the first analysis. */
static void skgl__depth_fit(skgl_shadow *s, float *zn, float *zf)
{
#ifdef SKGL_NO_FERKO   /* no analysis: the range stays */
    (void)zn;
    (void)zf;
    s->stats.depth_lo = s->stats.depth_hi = 0.0f;
#else
    float m = s->desc.sync_readback ? 1e-3f : 0.1f, lo, hi;
    s->stats.depth_lo = s->stats.depth_hi = 0.0f;
    if (!(s->desc.fit_to_depth || s->desc.technique == SKGL_AUTO) || s->ferko.state == 0 ||
        !(s->ferko.depth_hi > 0.0f))
        return;
    lo = s->ferko.depth_lo * (1.0f - m);
    hi = s->ferko.depth_hi * (1.0f + m);
    if (lo > *zn && lo < *zf) *zn = lo;
    if (hi < *zf && hi > *zn * 1.001f) *zf = hi;
    s->stats.depth_lo = *zn;
    s->stats.depth_hi = *zf;
#endif
}

/* The distance fade (desc.fade_band): where the scene goes on past the
   end of the shadows, they fade over the last part of the last layer's
   depth range; stored after the splits (skgl__shadow_uniforms). The end
   is splits[1] for LSPSM (one range, partitions by map), else
   splits[maps]. */
static void skgl__fade(skgl_shadow *s, float far_scene, const skgl_camera *cam, const skgl_scene *scene)
{
    float *sp = s->stats.splits, end, first;
    int i, last = s->desc.technique == SKGL_LSPSM ? 1 : s->maps;
    s->fade_start = SK__INF;
    if (s->desc.technique == SKGL_RMSM || s->desc.fade_band <= 0.0f || last < 1) return;
    if (!(far_scene > 0.0f))
        for (i = 0; i < 8; i++) {
            float depth = -sk__xform_affine(&cam->view, sk__aabb_corner(&scene->bounds, i)).z;
            if (depth > far_scene) far_scene = depth;
        }
    end = sp[last];
    first = sp[last - 1];
    if (!(end < far_scene * 0.999f)) return;   /* the scene ends first: no line to hide */
    s->fade_start = end - s->desc.fade_band * (end - first);
}

/* The split weight of the layers: .lambda, except that .fit_to_depth
   with .lambda left at 0 splits an analysed range logarithmically (lambda
   1), as sample distribution shadow maps do (Lauritzen, Salvi and Lefohn
   2011): the range starts at the nearest receiver seen, where the uniform
   term of the practical scheme (Zhang et al. 2006) only lengthens the
   first cascade (test_gl_auto, open world, PSSM 4x1024^2: 1.70% at 0.75,
   see skgl__auto_lambda for AUTO's same choice). */
static float skgl__split_lambda(const skgl_shadow *s)
{
    if (s->desc.lambda > 0.0f || s->desc.uniform_splits) return s->desc.lambda;
    return s->stats.depth_hi > 0.0f ? 1.0f : 0.75f;   /* .fit_to_depth, .lambda left 0 */
}

/* Crops of every layer: the PSSM practical split scheme (Romanick's VGP353 notes) over
   the part of the view that can hold receivers; per layer a focused crop of
   the slice clipped to the scene, or a texel-snapped stable crop. */
static sk_result skgl__fit_layers(skgl_shadow *s, const skgl_camera *cam, const skgl_scene *scene, sk_vec3 light_dir)
{
    const skgl_shadow_desc *d = &s->desc;
    sk_mat4 cam_vp = sk_mat4_mul(cam->proj, cam->view);
    skgl__fit_in in;
    float zn, cam_zf, zf, far_scene = 0.0f, shadow_zn;
    int i;
    sk_result r;
    in.cam = cam;
    in.scene = scene;
    in.light_dir = light_dir;
    in.lview = sk_light_view_directional(light_dir);
    in.view = sk_frustum_from_matrix(cam_vp);
    if (!skgl__near_far(&cam->proj, &zn, &cam_zf) || sk__frustum_invalid(&in.view)) return SK_ERR_INVALID_ARG;
    /* shadows end at max_distance, and (focused mode only) where the scene
       ends: stable mode needs a range that does not depend on where the
       camera is, or the cascade spheres and their texels would change size */
    zf = cam_zf;
    if (!d->stable || skgl__stepped(d)) {
        for (i = 0; i < 8; i++) {
            float depth = -sk__xform_affine(&cam->view, sk__aabb_corner(&scene->bounds, i)).z;
            if (depth > far_scene) far_scene = depth;
        }
        /* stable: the end steps on the ladder, so the splits stay put while
           the camera moves a little (STABLE CROPS) */
        if (d->stable) {
            int was = s->far_step;
            if (skgl__camera_cut(s, cam)) skgl__restart_steps(s);
            s->step_view = cam->view;
            skgl__world_eye(s, cam, s->step_eye);
            s->far_step = skgl__ladder_step(far_scene, s->far_step, &s->far_below);
            /* a new end moves every split: a crop whose need has fallen two
               steps shrinks now, rather than settling again from naught */
            if (s->far_step != was) skgl__settled_layer_steps(s);
            if (s->far_step != SKGL__NO_STEP) far_scene = (float)skgl__ladder(s->far_step);
        }
        if (far_scene < zf) zf = far_scene > zn * 1.001f ? far_scene : zn * 1.001f;
    }
    if (d->max_distance > zn && d->max_distance < zf) zf = d->max_distance;
    shadow_zn = zn;
    skgl__depth_fit(s, &shadow_zn, &zf);
    if (skgl__splits(d, skgl__split_lambda(s), s->layers, shadow_zn, zf, s->stats.splits) != SK_OK)
        return SK_ERR_INVALID_ARG;
    s->stats.depth_reversed = 0;
    s->stats.psm_slide = 0.0f;
    s->maps = s->layers;
    s->stats.lspsm_fallback = 0;
    for (i = 0; i < s->layers; i++) { s->stats.warp_n[i] = SK__INF; s->stats.warped[i] = 0; }
    s->view_w = s->view_h = d->resolution;
    in.zn = zn;
    in.cam_zf = cam_zf;
    in.zf = zf;
    in.shadow_zn = shadow_zn;
    r = skgl__technique_of(s)->fit(s, &in);
    skgl__fade(s, far_scene, cam, scene);
    return r;
}

/* layer i's slice of the view, from its split (less the blend band of
   the layer before: layer i is also sampled in the blend region at the end
   of layer i-1, [s_i - band, s_i), so its crop covers that region too, or
   the blend would fade toward "outside the map", lit); *z0: where it starts */
static sk_result skgl__slice_of(const skgl_shadow *s, const skgl__fit_in *in, const float *sp, int i,
                                sk_frustum *slice, float *z0)
{
    *z0 = i > 0 ? sp[i] - s->desc.blend_band * (sp[i] - sp[i - 1]) : sp[0];
    return sk_frustum_slice(&in->view, in->zn, in->cam_zf, *z0, sp[i + 1], slice);
}

static sk_result skgl__layer_slice(const skgl_shadow *s, const skgl__fit_in *in, int i, sk_frustum *slice, float *z0)
{
    return skgl__slice_of(s, in, s->stats.splits, i, slice, z0);
}

/* the focused crop of a slice: its part inside the scene (the whole slice
   when none is), fitted in light space */
static sk_result skgl__focused_crop(const skgl__fit_in *in, const sk_frustum *slice, sk_mat4 *proj)
{
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    int n = sk_clip_frustum_aabb(slice, in->scene->bounds, pts, SK_CLIP_MAX_POINTS);
    return n > 0 ? sk_fit_ortho(pts, n, in->lview, &in->scene->bounds, proj)
                 : sk_fit_ortho(slice->corners, 8, in->lview, &in->scene->bounds, proj);
}

/* A cached stable crop's depth range: the scene's bounds in light space
   (a little wider), which do not move with the camera; the crop's own
   (the cascade's sphere) would change every cached texel's depth as the
   camera walks (CACHED MAPS). */
static void skgl__scene_depth_range(sk_mat4 *proj, const sk_mat4 *lview, const sk_aabb *bounds)
{
    double zmin = 1e300, zmax = -1e300, n, f, pad;
    int i;
    for (i = 0; i < 8; i++) {
        double z = sk__xform_affine(lview, sk__aabb_corner(bounds, i)).z;
        if (z < zmin) zmin = z;
        if (z > zmax) zmax = z;
    }
    pad = 1e-4 * (zmax - zmin) + 1e-4;
    n = -zmax - pad;
    f = -zmin + pad;
    proj->m[10] = (float)(-2.0 / (f - n));
    proj->m[14] = (float)(-(f + n) / (f - n));
}

/* A stable crop (.stable without .stable_sphere): the focused crop's
   light-space box of the slice clipped to the scene, its width and its
   height each widened to a ladder step (skgl__ladder_step, per layer and
   axis), its corner snapped to whole texels of a grid fixed in world light
   space. The texel size changes only when the view's need crosses a step
   (a camera turning or rising far enough), never as it moves a little: no
   shimmer. */
static sk_result skgl__stepped_crop(skgl_shadow *s, const skgl__fit_in *in, int i, const sk_vec3 *pts, int n,
                                    sk_mat4 *proj)
{
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, tx, ty, x0, y0, ox = 0.0, oy = 0.0;
    const float *m = in->lview.m;
    int res = s->desc.resolution, j, k;
    float b[6];
    for (j = 0; j < n; j++) {
        sk_vec3 p = sk__xform_affine(&in->lview, pts[j]);
        for (k = 0; k < 3; k++) {
            if ((&p.x)[k] < lo[k]) lo[k] = (&p.x)[k];
            if ((&p.x)[k] > hi[k]) hi[k] = (&p.x)[k];
        }
    }
    hi[2] = sk__casters_zmax(&in->lview, &in->scene->bounds, hi[2]);
    for (k = 0; k < 2; k++) {
        s->step[i][k] = skgl__ladder_step(hi[k] - lo[k], s->step[i][k], &s->step_below[i][k]);
        if (s->step[i][k] == SKGL__NO_STEP) return SK_ERR_DEGENERATE;
    }
    tx = skgl__ladder(s->step[i][0]) / (res - 1);
    ty = skgl__ladder(s->step[i][1]) / (res - 1);
    /* the origin's place in light-view space (rotation only), so that the
       grid is fixed in the world, not at the light's origin */
    ox = (double)m[0] * s->origin[0] + (double)m[4] * s->origin[1] + (double)m[8] * s->origin[2];
    oy = (double)m[1] * s->origin[0] + (double)m[5] * s->origin[1] + (double)m[9] * s->origin[2];
    x0 = SK_FLOOR((0.5 * (lo[0] + hi[0]) - 0.5 * tx * (res - 1) + ox) / tx) * tx - ox;
    y0 = SK_FLOOR((0.5 * (lo[1] + hi[1]) - 0.5 * ty * (res - 1) + oy) / ty) * ty - oy;
    b[0] = (float)x0; b[1] = (float)(x0 + tx * res); b[2] = (float)y0; b[3] = (float)(y0 + ty * res);
    b[4] = (float)-hi[2]; b[5] = (float)-lo[2];
    for (k = 0; k < 6; k++) if (!sk__finite(b[k])) return SK_ERR_DEGENERATE;
    if (!(b[1] > b[0]) || !(b[3] > b[2]) || !(b[5] > b[4])) return SK_ERR_DEGENERATE;
    *proj = sk_mat4_ortho(b[0], b[1], b[2], b[3], b[4], b[5]);
    return SK_OK;
}

/* per layer: STANDARD, PSSM a focused crop of the slice clipped to the
   scene, or (.stable) the crop of a sphere that depends only on the
   camera's projection and the splits; LiSPSM (warp = 1) a warp of the
   slice's receivers */
static sk_result skgl__fit_slices(skgl_shadow *s, const skgl__fit_in *in, int warp)
{
    const skgl_shadow_desc *d = &s->desc;
    int i;
    for (i = 0; i < s->maps; i++) {
        sk_frustum slice;
        sk_mat4 proj;
        float z0;
        sk_result r = skgl__layer_slice(s, in, i, &slice, &z0);
        if (r != SK_OK) return r;
        if (warp) {
            r = skgl__fit_lispsm(s, i, in->cam, in->scene, in->light_dir, &slice, z0);
            if (r != SK_OK) return r;
            continue;
        }
        if (skgl__stepped(d)) {
            sk_vec3 pts[SK_CLIP_MAX_POINTS];
            int n = sk_clip_frustum_aabb(&slice, in->scene->bounds, pts, SK_CLIP_MAX_POINTS);
            r = n > 0 ? skgl__stepped_crop(s, in, i, pts, n, &proj) : skgl__stepped_crop(s, in, i, slice.corners, 8, &proj);
        } else if (d->stable) {
            /* radius from the camera's parameters only: bitwise the same
               wherever the camera goes (fovy and aspect of a GL perspective) */
            const sk_mat4 *pr = &in->cam->proj;
            float fovy = (float)(2.0 * SK_ATAN(1.0 / pr->m[5])), aspect = pr->m[5] / pr->m[0];
            sk_sphere sph = sk_cascade_sphere(in->cam->view, fovy, aspect, z0, s->stats.splits[i + 1]);
            if (!(sph.r > 0.0f)) sph = sk_frustum_bounding_sphere(&slice);
            /* the texel grid fixed in world light space, not at the origin */
            r = sk_stable_crop_origin(sph, in->lview, d->resolution, &in->scene->bounds,
                                      s->origin[0] == 0.0 && s->origin[1] == 0.0 && s->origin[2] == 0.0 ? NULL
                                                                                                          : s->origin,
                                      &proj);
            if (r == SK_OK && d->cache) skgl__scene_depth_range(&proj, &in->lview, &in->scene->bounds);
        } else {
            r = skgl__focused_crop(in, &slice, &proj);
            if (d->technique == SKGL_AUTO) s->stats.auto_crops++;
        }
        if (r != SK_OK) return r;
        s->vp[i] = sk_mat4_mul(proj, in->lview);
    }
    return SK_OK;
}

static sk_result skgl__fit_ortho_layers(skgl_shadow *s, const skgl__fit_in *in)
{
    return skgl__fit_slices(s, in, 0);
}

/* LiSPSM: one warp per layer (a single one with .cascades 1) */
static sk_result skgl__fit_lispsm_layers(skgl_shadow *s, const skgl__fit_in *in)
{
    return skgl__fit_slices(s, in, 1);
}

static sk_result skgl__fit_psm_layer(skgl_shadow *s, const skgl__fit_in *in)
{
    return skgl__fit_psm(s, in->cam, in->scene, in->light_dir, &in->view, in->zn, in->cam_zf, in->zf);
}

static sk_result skgl__fit_lspsm_layers(skgl_shadow *s, const skgl__fit_in *in)
{
    return skgl__fit_lspsm(s, in->cam, in->scene, in->light_dir, &in->view, in->zn, in->cam_zf, in->zf);
}

#ifndef SKGL_NO_FERKO
/* FERKO: the estimate's crop once there is one, the focused map before */
static sk_result skgl__fit_ferko_layer(skgl_shadow *s, const skgl__fit_in *in)
{
    if (s->ferko.state == 0) return skgl__fit_ortho_layers(s, in);
    skgl__fit_ferko(s, in->cam_zf > in->zf ? in->cam_zf : in->zf);
    return SK_OK;
}

/* ---- 6.2, continued: AUTO, the library chooses (CHOOSING FOR YOU) ---- */
// >>auto
/* The light-space width of a focused crop (its larger side), from its
   orthographic projection */
static float skgl__crop_side(const sk_mat4 *proj)
{
    float w = 2.0f / SK_FABSF(proj->m[0]), h = 2.0f / SK_FABSF(proj->m[5]);
    return w > h ? w : h;
}

/* The side of each of n maps that share .resolution^2 texels */
static int skgl__auto_side(int res, int n)
{
    int side = (int)SK_FLOOR((double)res / SK_SQRT((double)n));
    return side < 16 ? 16 : side;
}

/* AUTO's split weight: Zhang, Sun, Xu and Lun 2006's practical split
   scheme, C_i = lambda C_i^log + (1 - lambda) C_i^uni (the form of
   Romanick's VGP353 notes, week 5, which number no equation). Over a
   range [n, f] the logarithmic splits give every cascade the same ratio
   C_i+1 / C_i = (f / n)^(1/m), and the texel-to-pixel ratio at a
   cascade's near end grows with that ratio alone: the log scheme spreads
   the perspective aliasing evenly. The uniform term is the paper's remedy
   for a near plane far in front of every receiver, whose log splits
   spend the first cascades on empty space. Once the analysis has measured
   the view depths (the shadow range starts at the nearest receiver
   seen, sample distribution shadow maps, Lauritzen, Salvi and Lefohn 2011)
   that waste is gone: lambda 1, the log scheme, whatever the range (over
   a small range f / n is small and the two schemes nearly agree). Before
   the first analysis the range starts at the near plane: .lambda [0.75].
   Measured (test_gl_auto, open world, 2048^2 of texels, pooled error):
   4 maps 1.70% at lambda 0.75, 1.08% at 0.9, 1.03% at 1; 3 maps 1.95,
   1.41, 1.33%; 2 maps 2.68, 1.60, 1.51%; on the small scenes every
   lambda within 0.05 point. */
static float skgl__auto_lambda(const skgl_shadow *s, const skgl__fit_in *in)
{
    if (!(in->shadow_zn > 0.0f)) return 0.0f;   /* an orthographic view from depth 0: uniform */
    return s->stats.depth_hi > 0.0f ? 1.0f : s->desc.lambda;
}

/* one count AUTO tries: its splits, its focused crops (kept for the
   count chosen, so that each crop is fitted once), its worst
   texel-to-pixel ratio (0: a slice or a crop did not fit); the same
   slices warped (LiSPSM), their light matrices and worst ratio (0: not
   tried, or a warp did not fit) */
typedef struct skgl__auto_try {
    float sp[SKGL_MAX_CASCADES + 1];
    sk_mat4 proj[SKGL_MAX_CASCADES];
    float ratio;
    sk_mat4 warp_vp[SKGL_MAX_CASCADES];
    float warp_n[SKGL_MAX_CASCADES];
    int warped[SKGL_MAX_CASCADES];
    float warp_ratio;
} skgl__auto_try;

/* The texel-to-pixel ratio of a light matrix vp (relative to the camera,
   like the fit's; drawn into side^2 texels) at view depth d on the view's
   central ray. The map's Jacobian there, d(ndc.xy) over the two world axes
   across the light (vp projective: d(c.x / c.w) = (row0 - ndc.x row3) / c.w),
   its smaller singular value s: a texel spans 2 / (side s) world units at
   most, against a pixel's footprint 2 d / (P[1][1] H). 0: undefined there
   (behind the map's eye, or a singular Jacobian). */
static float skgl__texel_px_at(const sk_mat4 *vp, const sk_mat4 *lview, const skgl_camera *cam, float d, int side,
                               float px_h)
{
    const float *m = vp->m, *l = lview->m, *v = cam->view.m;
    double eye[3], p[3], c[4], j[2][3], a[2][3], q[2][2], t, det, tr, disc, smin;
    int r, k;
    skgl__view_eye(&cam->view, eye);
    for (r = 0; r < 3; r++) p[r] = eye[r] - (double)d * v[r * 4 + 2];   /* along -z of the eye */
    for (k = 0; k < 4; k++) c[k] = (double)m[k] * p[0] + (double)m[4 + k] * p[1] + (double)m[8 + k] * p[2] + m[12 + k];
    if (!(c[3] > 0.0)) return 0.0f;
    for (r = 0; r < 2; r++)
        for (k = 0; k < 3; k++) j[r][k] = ((double)m[k * 4 + r] - c[r] / c[3] * m[k * 4 + 3]) / c[3];
    for (k = 0; k < 3; k++) {   /* the light view's x and y axes in world space: its first two rows */
        a[0][k] = l[k * 4];
        a[1][k] = l[k * 4 + 1];
    }
    for (r = 0; r < 2; r++)
        for (k = 0; k < 2; k++) q[r][k] = j[r][0] * a[k][0] + j[r][1] * a[k][1] + j[r][2] * a[k][2];
    /* smaller singular value of the 2x2 q: sqrt of the smaller eigenvalue of q^T q */
    tr = q[0][0] * q[0][0] + q[0][1] * q[0][1] + q[1][0] * q[1][0] + q[1][1] * q[1][1];
    det = q[0][0] * q[1][1] - q[0][1] * q[1][0];
    disc = tr * tr - 4.0 * det * det;
    smin = SK_SQRT(0.5 * (tr - SK_SQRT(disc > 0.0 ? disc : 0.0)));
    if (!(smin > 0.0)) return 0.0f;
    t = 2.0 / ((double)side * smin) / (2.0 * (double)d / (SK_FABSF(cam->proj.m[5]) * (double)px_h));
    return t < 1e30 ? (float)t : 0.0f;
}

/* A warped map's worst texel-to-pixel ratio over its slice [d0, d1]: at
   four depths spaced evenly in log (a warp spreads its texels over the
   slice, so the worst place need not be the near end). 0: undefined. */
static float skgl__warp_texel_px(const sk_mat4 *vp, const sk_mat4 *lview, const skgl_camera *cam, float d0,
                                 float d1, int side, float px_h)
{
    float worst = 0.0f;
    int k;
    for (k = 0; k < 4; k++) {
        float d = (float)((double)d0 * SK_POW((double)d1 / (double)d0, (double)k / 3.0));
        float t = skgl__texel_px_at(vp, lview, cam, d, side, px_h);
        if (!(t > 0.0f)) return 0.0f;
        if (t > worst) worst = t;
    }
    return worst;
}

/* The same n slices warped (LiSPSM, one warp a slice as SKGL_LISPSM with
   .cascades n fits them) and their worst ratio (skgl__warp_texel_px) in
   t->warp_ratio; 0 when a warp does not fit, or when no slice is warped
   (sk_lispsm_result.warped: a light along the view leaves every map
   uniform, the focused crops then). */
static void skgl__auto_score_warp(skgl_shadow *s, const skgl__fit_in *in, int n, int side, float px_h,
                                  skgl__auto_try *t)
{
    float worst = 0.0f;
    int i, any = 0;
    for (i = 0; i < n; i++) {
        sk_frustum slice;
        sk_lispsm_result lr;
        float z0, ratio;
        if (skgl__slice_of(s, in, t->sp, i, &slice, &z0) != SK_OK) return;
        if (skgl__lispsm_warp(in->cam, in->scene, in->light_dir, &slice, z0, &lr) != SK_OK) return;
        ratio = skgl__warp_texel_px(&lr.light_view_proj, &in->lview, in->cam, t->sp[i], t->sp[i + 1], side, px_h);
        if (!(ratio > 0.0f)) return;
        if (ratio > worst) worst = ratio;
        t->warp_vp[i] = lr.light_view_proj;
        t->warp_n[i] = lr.n;
        t->warped[i] = lr.warped;
        any |= lr.warped;
    }
    if (any) t->warp_ratio = worst;
}

/* With n cascades over [in->shadow_zn, in->zf] split with lambda, the
   largest ratio over the cascades of a texel (the crop's larger side
   over the map's side) to a pixel's footprint at the cascade's near end
   (2 d tan(fovy / 2) / the view's height in pixels): the texel-to-pixel
   ratio the worst place of the view gets. Counts the crops it fits in
   stats.auto_crops. */
static void skgl__auto_score(skgl_shadow *s, const skgl__fit_in *in, int n, float lambda, float px_h,
                             skgl__auto_try *t)
{
    const sk_mat4 *pr = &in->cam->proj;
    float worst = 0.0f;
    int i, side = skgl__auto_side(s->desc.resolution, n);
    int persp = pr->m[11] != 0.0f;
    t->ratio = 0.0f;
    if (n == 1) {
        t->sp[0] = in->shadow_zn;
        t->sp[1] = in->zf;
    } else if (sk_pssm_splits(in->shadow_zn, in->zf, n, lambda, t->sp) != SK_OK) {
        return;
    }
    t->warp_ratio = 0.0f;
    for (i = 0; i < n; i++) {
        sk_frustum slice;
        float z0, pixel, ratio;
        if (skgl__slice_of(s, in, t->sp, i, &slice, &z0) != SK_OK) return;
        s->stats.auto_crops++;
        if (skgl__focused_crop(in, &slice, &t->proj[i]) != SK_OK) return;
        /* pixel footprint: perspective 2 d / (P[1][1] H), orthographic 2 / (P[1][1] H) */
        pixel = (persp ? 2.0f * t->sp[i] : 2.0f) / (SK_FABSF(pr->m[5]) * px_h);
        ratio = skgl__crop_side(&t->proj[i]) / (float)side / pixel;
        if (!(ratio < 1e30f)) return;
        if (ratio > worst) worst = ratio;
    }
    t->ratio = worst;
    if (persp && !s->desc.disable_auto_warp) skgl__auto_score_warp(s, in, n, side, px_h, t);
}

/* AUTO's rule: of 1 to .cascades maps sharing .resolution^2 texels, each
   focused or warped (candidate c: c / 2 + 1 maps, warped when c is odd),
   the fewest maps whose worst texel-to-pixel ratio (skgl__auto_score) is
   at most .auto_texel_px, the smaller ratio of the two at that count;
   else the fewest maps within 25% of the smallest ratio. Hysteresis, so
   that two candidates that score alike do not alternate: the one in use
   is kept unless the new one's ratio is 15% smaller, or it has fewer maps
   and meets 0.85 of the target (or, the one in use missing the target,
   is at most 1.25 / 1.15 = 9% coarser: a set 9-25% coarser with fewer
   maps is picked afresh but not switched to, so a score wavering about
   the 25% line does not swap the sets back and forth), or the one in use
   misses the target by more than 15% and the new one meets it. One focused map is SKGL_STANDARD's
   crop, more are SKGL_PSSM's cascades, warped ones SKGL_LISPSM's (with
   .cascades n); the maps share the texels, so each is drawn into the
   lower-left side x side texels of its layer. */
#define SKGL__AUTO_MAPS(c) ((c) / 2 + 1)
/* a map more, when no set meets the target, must make the texels this much
   finer. Measured on the bench: at 1.15 the curtains' close view at 2048^2
   took 2 warped maps (2.01 px) over one (2.05 px; the finest set 1.76),
   11.5% error in 44 ms against one warped map's 10.4% in 28 ms */
#define SKGL__AUTO_MAP_GAIN 1.25f
static int skgl__auto_pick(const float *score, int cands, int cur, float target)
{
    int c, pick = -1, low = -1;
    for (c = 0; c < cands; c++) {
        if (!(score[c] > 0.0f)) continue;
        if (score[c] <= target &&
            (pick < 0 || (SKGL__AUTO_MAPS(c) == SKGL__AUTO_MAPS(pick) && score[c] < score[pick])))
            pick = c;
        if (low < 0 || score[c] < score[low]) low = c;
    }
    if (low < 0) return -1;   /* nothing fitted: the fit reports it */
    if (pick < 0) {
        /* none meets the target: the fewest maps within SKGL__AUTO_MAP_GAIN
           of the finest (a map more costs a caster pass) */
        for (c = 0; c < cands; c++)
            if (score[c] > 0.0f && score[c] <= SKGL__AUTO_MAP_GAIN * score[low] &&
                (pick < 0 || SKGL__AUTO_MAPS(c) < SKGL__AUTO_MAPS(pick) ||
                 (SKGL__AUTO_MAPS(c) == SKGL__AUTO_MAPS(pick) && score[c] < score[pick])))
                pick = c;
    }
    if (cur < 0 || cur >= cands || !(score[cur] > 0.0f)) return pick;
    if (score[pick] < 0.85f * score[cur] ||
        (SKGL__AUTO_MAPS(pick) < SKGL__AUTO_MAPS(cur) &&
         (score[pick] <= 0.85f * target ||
          (score[cur] > target && 1.15f * score[pick] <= SKGL__AUTO_MAP_GAIN * score[cur]))) ||
        (score[cur] > 1.15f * target && score[pick] <= target))
        return pick;
    return cur;
}

static sk_result skgl__fit_auto(skgl_shadow *s, const skgl__fit_in *in)
{
    skgl__auto_try t[SKGL_MAX_CASCADES];
    float score[2 * SKGL_MAX_CASCADES], px_h = s->ferko.h > 0 ? (float)s->ferko.h : (float)s->desc.resolution;
    float target = s->desc.auto_texel_px, lambda = skgl__auto_lambda(s, in);
    int n, c, cur, warp, side, i;
    s->stats.auto_crops = 0;
    for (n = 1; n <= SKGL_MAX_CASCADES; n++) {
        t[n - 1].ratio = t[n - 1].warp_ratio = 0.0f;
        if (n <= s->layers) skgl__auto_score(s, in, n, lambda, px_h, &t[n - 1]);
        score[2 * (n - 1)] = s->stats.auto_texel_px[n - 1] = t[n - 1].ratio;
        score[2 * (n - 1) + 1] = s->stats.auto_texel_px_warped[n - 1] = t[n - 1].warp_ratio;
    }
    /* the first analysed range: the set picked over the whole view before
       it is no set in use to keep (hysteresis is for a view that moves) */
    cur = s->stats.depth_hi > 0.0f && !s->auto_pick_analysed ? -1 : s->auto_pick;
    s->auto_pick_analysed = s->stats.depth_hi > 0.0f;
    c = skgl__auto_pick(score, 2 * s->layers, cur, target);
    if (c < 0) c = 2 * (s->layers - 1);
    n = SKGL__AUTO_MAPS(c);
    warp = c & 1;
    s->maps = n;
    s->stats.auto_technique = warp ? SKGL_LISPSM : n == 1 ? SKGL_STANDARD : SKGL_PSSM;
    s->stats.auto_lambda = n == 1 ? 0.0f : lambda;
    snprintf(s->stats.auto_reason, sizeof s->stats.auto_reason,
             "%d %smap%s: a texel spans %.2f px at worst, target %.2f%s; depths %.3g..%.3g%s, lambda %.2g", n,
             warp ? "warped " : "", n > 1 ? "s" : "", (double)score[c], (double)target,
             c == cur ? " (kept)" : "", (double)in->shadow_zn, (double)in->zf,
             s->stats.depth_hi > 0.0f ? "" : " (no analysis yet)", (double)s->stats.auto_lambda);
    s->auto_pick = c;
    if (score[c] > 0.0f) {
        /* the crops (or warps) the score fitted */
        memcpy(s->stats.splits, t[n - 1].sp, (size_t)(n + 1) * sizeof(float));
        for (i = 0; i < n; i++) {
            if (warp) {
                s->vp[i] = t[n - 1].warp_vp[i];
                s->stats.warp_n[i] = t[n - 1].warp_n[i];
                s->stats.warped[i] = t[n - 1].warped[i];
            } else {
                s->vp[i] = sk_mat4_mul(t[n - 1].proj[i], in->lview);
            }
        }
    } else {
        /* no count fitted: the layers' own fit says why */
        sk_result r;
        if (skgl__splits(&s->desc, s->desc.lambda, n, in->shadow_zn, in->zf, s->stats.splits) != SK_OK)
            return SK_ERR_INVALID_ARG;
        r = skgl__fit_slices(s, in, 0);
        if (r != SK_OK) return r;
    }
    side = skgl__auto_side(s->desc.resolution, n);
    s->view_w = s->view_h = side < s->desc.resolution ? side : s->desc.resolution;
    return SK_OK;
}

/* AUTO's depth texture: n maps of side^2 need n layers of side^2. A count
   that does not fit the texture makes it grow at once, to hold both the
   old count and the new (a camera going back and forth between two counts
   then draws into what is there); once a count has been kept for
   SKGL__AUTO_SHRINK renders, a texture larger than it needs shrinks to
   exactly its layers and side. A map smaller than the texture is drawn
   into the lower-left side x side texels of its layer (its lookup matrix
   scaled to them, sk_map_extent), and llvmpipe draws such a map about
   1.4x slower than into a layer of its own size (the depth passes of the
   open world's 4 maps of 1024^2: 37 against 25 ms for PSSM 4 x 1024^2, a
   layer of 2048^2 under each). Re-specified in place (glTexImage3D on the
   same name), with new framebuffers for its layers; EVSM's moments follow
   its size. */
#define SKGL__AUTO_SHRINK 30
static sk_result skgl__auto_storage(skgl_context *ctx, skgl_shadow *s)
{
    skgl__api *gl = &ctx->gl;
    skgl__st st;
    sk_result r = SK_OK;
    int n = s->maps, side = s->view_w, size, layers, i;
    if (n != s->auto_maps_drawn) s->auto_settled = 0;
    s->auto_maps_drawn = n;
    if (s->auto_settled < SKGL__AUTO_SHRINK) s->auto_settled++;
    if (!s->auto_sized || s->auto_settled >= SKGL__AUTO_SHRINK) {
        size = side;
        layers = n;
    } else {
        size = side > s->tex_size ? side : s->tex_size;
        layers = n > s->tex_layers ? n : s->tex_layers;
    }
    s->auto_sized = 1;
    if (size == s->tex_size && layers == s->tex_layers) return SK_OK;
    skgl__st_begin(ctx, &st);
    for (i = 0; i < SKGL_MAX_CASCADES; i++) skgl__delete_framebuffer(ctx, &s->fbo[i]);
    skgl__delete_framebuffer(ctx, &s->fbo_layered);
    skgl__st_unpack(ctx, &st);
    skgl__st_set1(ctx, &st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY), (skgl__int)s->tex);
    skgl__st_unit(ctx, &st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    gl->TexImage3D(SKGL__TEXTURE_2D_ARRAY, 0, SKGL__DEPTH_COMPONENT32F, size, size, layers, 0,
                   SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    s->tex_size = size;
    s->tex_layers = layers;
    for (i = 0; i < layers && r == SK_OK; i++)
        if (!(s->fbo[i] = skgl__framebuffer(ctx, &st, 0, 0, s->tex, i))) r = SK_ERR_GL;
    if (r == SK_OK && s->desc.filter == SKGL_FILTER_EVSM) {
        skgl__evsm_free(ctx, s);
        r = skgl__evsm_create(ctx, &st, s);
    }
    skgl__st_end(ctx, &st);
    if (r != SK_OK) skgl__set_log(ctx, "skgl_shadow_render: SKGL_AUTO's depth texture at its new size", NULL);
    return r;
}

static sk_result skgl__render_layers(skgl_context *ctx, skgl_shadow *s, const skgl_scene *rs, sk_vec3 light_dir);
/* AUTO: its texture sized to the count (skgl__auto_storage), each map's
   lookup matrix onto its part of the layer, then the layers' passes */
static sk_result skgl__render_auto(skgl_context *ctx, skgl_shadow *s, const skgl_scene *rs, sk_vec3 light_dir)
{
    int i;
    sk_result r = skgl__auto_storage(ctx, s);
    if (r != SK_OK) return r;
    s->stats.auto_bytes = 4.0 * s->tex_layers * (double)s->tex_size * s->tex_size;
    for (i = 0; i < s->maps && s->view_w < s->tex_size; i++) {
        sk_mat4 m = sk_mat4_identity();
        float f = (float)s->view_w / (float)s->tex_size;
        m.m[0] = m.m[5] = f;
        m.m[12] = m.m[13] = f - 1.0f;
        s->render_vp[i] = s->vp[i];
        s->vp[i] = sk_mat4_mul(m, s->vp[i]);
    }
    return skgl__render_layers(ctx, s, rs, light_dir);
}
#endif /* SKGL_NO_FERKO */

#ifndef SKGL_NO_RMSM
/* RMSM: the pages are fitted by skgl__render_rmsm */
static sk_result skgl__fit_rmsm(skgl_shadow *s, const skgl__fit_in *in)
{
    (void)in;
    s->maps = 1;
    return SK_OK;
}
#endif

/* ---- 6.3 FERKO: resolution estimation on the GPU (Ferko 2013) --------- */
// >>ferko
#ifndef SKGL_NO_FERKO
static void skgl__ferko_free(skgl_context *ctx, skgl_shadow *s)
{
    int i;
    for (i = 0; i < 3; i++) {
        skgl__delete_texture(ctx, &s->ferko.tex[i]);
        skgl__delete_framebuffer(ctx, &s->ferko.fbo[i]);
    }
    s->ferko.w = s->ferko.h = s->ferko.levels = 0;
}

/* the estimate's 2x1 texels and their read-back ring (the analysis
   targets follow the G-buffer's size: skgl__ferko_targets) */
static sk_result skgl__ferko_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    SKGL__TRY(skgl__ferko_programs(ctx, st));
    s->ferko.final = skgl__color_texture(ctx, st, SKGL__RGBA32F, 2, 1, 1, SKGL__RGBA, SKGL__FLOAT, NULL);
    s->ferko.final_fbo = skgl__framebuffer(ctx, st, s->ferko.final, 1, 0, 0);
    skgl__ring_create(ctx, st, &s->ferko.ring, 8 * sizeof(float));
    if (!s->ferko.final_fbo) return skgl__fail(ctx, SK_ERR_GL, "skgl_shadow_create: RGBA32F targets not renderable");
    return SK_OK;
}

static void skgl__ferko_destroy(skgl_context *ctx, skgl_shadow *s)
{
    skgl__ferko_free(ctx, s);
    skgl__delete_texture(ctx, &s->ferko.final);
    skgl__delete_framebuffer(ctx, &s->ferko.final_fbo);
    skgl__ring_free(ctx, &s->ferko.ring);
}

/* The analysis targets for a w x h G-buffer: level 0, the analysis, at 1/4
   (a texel per 4x4 pixels), each later level 1/16 of the one before (a
   texel per 16x16), until one of at most 32 x 32 texels is left for the
   final pass (1280 x 720: 320 x 180, 20 x 12, then the final). Each level
   is a 2-layer RGBA32F texture (bounds, patch) with its framebuffer;
   levels from 3 on (G-buffers past 16384 pixels a side) take turns in the
   textures of levels 1 and 2, which are larger. 1 when every framebuffer
   is complete. */
static int skgl__ferko_targets(skgl_context *ctx, skgl__st *st, skgl_shadow *s, int w, int h)
{
    int k, lw = (w + 3) / 4, lh = (h + 3) / 4, ok = 1;
    if (s->ferko.w == w && s->ferko.h == h) return 1;
    skgl__ferko_free(ctx, s);
    for (k = 0; k < SKGL__FERKO_LEVELS; k++) {
        s->ferko.lw[k] = lw;
        s->ferko.lh[k] = lh;
        if (k < 3) {
            s->ferko.tex[k] = skgl__color_texture(ctx, st, SKGL__RGBA32F, lw, lh, 2, SKGL__RGBA, SKGL__FLOAT, NULL);
            s->ferko.fbo[k] = skgl__framebuffer(ctx, st, s->ferko.tex[k], 2, 0, 0);
            ok &= s->ferko.fbo[k] != 0;
        }
        if (lw <= 32 && lh <= 32) break;
        lw = (lw + 15) / 16;
        lh = (lh + 15) / 16;
    }
    s->ferko.levels = k < SKGL__FERKO_LEVELS ? k + 1 : SKGL__FERKO_LEVELS;
    s->ferko.w = w;
    s->ferko.h = h;
    return ok;
}

/* level k's texture and framebuffer */
static int skgl__ferko_slot(int k) { return k < 3 ? k : 1 + (k - 1) % 2; }

/* "nothing there" in a reduced channel (the shaders' SK_BIG, 3e38) */
#define SKGL__REDUCED_NONE 1e38f

/* The reduced texel pair, (min x, min y, -max x, -max y) and (min patch
   width, min patch height, min view depth, -max view depth), to the
   estimate, with the same rules as sk_estimate_resolution (samples: 1 when
   any, the GPU counts none). */
static void skgl__ferko_estimate(const float v[8], int max_res, sk_res_estimate *e)
{
    double bw, bh, rw, rh;
    float tw = v[4], th = v[5];
    memset(e, 0, sizeof *e);
    e->bounds.x0 = -1.0f; e->bounds.y0 = -1.0f; e->bounds.x1 = 1.0f; e->bounds.y1 = 1.0f;
    e->crop = sk_mat4_identity();
    if (!(v[6] < SKGL__REDUCED_NONE) || !sk__finite(v[0]) || !sk__finite(v[1]) || !sk__finite(v[2]) || !sk__finite(v[3])) return;
    e->bounds.x0 = v[0]; e->bounds.y0 = v[1]; e->bounds.x1 = -v[2]; e->bounds.y1 = -v[3];
    bw = (double)e->bounds.x1 - e->bounds.x0;
    bh = (double)e->bounds.y1 - e->bounds.y0;
    if (!(v[4] < SKGL__REDUCED_NONE)) { tw = (float)(bw / max_res); th = (float)(bh / max_res); }
    rw = tw > 0.0f ? bw / tw : (double)max_res;
    rh = th > 0.0f ? bh / th : (double)max_res;
    e->width = !(rw < max_res) ? max_res : rw < 1.0 ? 1 : (int)SK_CEIL(rw);
    e->height = !(rh < max_res) ? max_res : rh < 1.0 ? 1 : (int)SK_CEIL(rh);
    e->texel_w = tw;
    e->texel_h = th;
    e->samples = 1;
    e->crop = sk_crop_matrix(e->bounds, -1.0f, 1.0f);
}
/* an analysis read back: its estimate, its depth range, the light
   frustum and origin it was made in */
static void skgl__ferko_land(skgl_shadow *s, const float v[8], const sk_mat4 *lvp, const double o[3])
{
    skgl__ferko_estimate(v, s->desc.resolution, &s->ferko.est);
    s->ferko.depth_lo = s->ferko.depth_hi = 0.0f;
    if (v[6] < SKGL__REDUCED_NONE && v[7] < SKGL__REDUCED_NONE && v[6] > 0.0f && -v[7] >= v[6]) {
        s->ferko.depth_lo = v[6];
        s->ferko.depth_hi = -v[7];
    }
    s->ferko.lvp = *lvp;
    memcpy(s->ferko.origin, o, sizeof s->ferko.origin);
    s->ferko.state = 1;
}

/* the map of the estimate: its crop widened by a margin of texels (the
   normal offset and the PCF footprint of a sample at the crop's edge stay in
   the rendered region), rendered into the texture's lower-left w x h texels;
   the lookup matrix maps the crop onto that region */
static void skgl__fit_ferko(skgl_shadow *s, float zf)
{
    const sk_res_estimate *e = &s->ferko.est;
    int res = s->desc.resolution, w = e->width, h = e->height;
    int margin = skgl__filter_reach(&s->desc) + 2 + (int)SK_CEIL(s->desc.normal_bias > 0.0f ? s->desc.normal_bias : 0.0f);
    sk_mat4 m, t = sk_mat4_identity(), lvp = skgl__shift(&s->ferko.lvp, s->ferko.origin, s->origin);
    sk_rect b = e->bounds;
    if (e->samples > 0 && w > 0 && h > 0) {
        float mx = margin * (b.x1 - b.x0) / (float)w, my = margin * (b.y1 - b.y0) / (float)h;
        b.x0 -= mx; b.x1 += mx; b.y0 -= my; b.y1 += my;
        w += 2 * margin;
        h += 2 * margin;
        m = sk_mat4_mul(sk_crop_matrix(b, -1.0f, 1.0f), lvp);
    } else {
        w = h = 1;                               /* nothing visible in the light */
        m = lvp;
    }
    if (w > res) w = res;
    if (h > res) h = res;
    t.m[0] = (float)w / (float)res; t.m[12] = (float)w / (float)res - 1.0f;
    t.m[5] = (float)h / (float)res; t.m[13] = (float)h / (float)res - 1.0f;
    s->render_vp[0] = m;
    s->vp[0] = sk_mat4_mul(t, m);
    s->view_w = w;
    s->view_h = h;
    s->maps = 1;
    s->stats.splits[1] = zf;
    s->stats.estimate = *e;
    s->stats.estimate_light = skgl__shift(&s->ferko.lvp, s->ferko.origin, skgl__zero3);
}

#endif /* SKGL_NO_FERKO */

/* the uncropped light frustum: an orthographic map around the scene (RMSM's
   virtual map too) */
static sk_result skgl__ferko_light(const skgl_scene *scene, sk_vec3 light_dir, sk_mat4 *out)
{
    sk_vec3 c[8];
    sk_mat4 lview = sk_light_view_directional(light_dir), proj;
    int i;
    sk_result r;
    for (i = 0; i < 8; i++) c[i] = sk__aabb_corner(&scene->bounds, i);
    r = sk_fit_ortho(c, 8, lview, &scene->bounds, &proj);
    if (r == SK_OK) *out = sk_mat4_mul(proj, lview);
    return r;
}

#ifndef SKGL_NO_FERKO
/* an earlier frame's analysis, if it has landed (the last one kept if not) */
static void skgl__ferko_poll(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    float v[8];
    int slot;
    if (!s->desc.sync_readback && (slot = skgl__ring_poll(ctx, st, &s->ferko.ring, v)) >= 0)
        skgl__ferko_land(s, v, &s->ferko.ring.lvp[slot], s->ferko.ring.origin[slot]);
}

/* FERKO analysis: the 4x4-block pass, the 16x16 reductions, the final 2x1
   texels; read back at once (sync_readback, and the first analysis) or
   into the ring, the estimate of an earlier frame taken when it lands */
static sk_result skgl__analyze_ferko(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_camera *cam,
                                     const sk_mat4 *inv, const sk_mat4 *lvp, const double o[3], unsigned depth_tex,
                                     int w, int h)
{
    skgl__api *gl = &ctx->gl;
    sk_mat4 ndc_to_light;
    float world_w[4], v[8];
    int k, sync = s->desc.sync_readback || s->ferko.state == 0, slot;
    (void)cam;   /* the depth buffer's positions come through inv */
    if (!skgl__ferko_targets(ctx, st, s, w, h)) {
        skgl__ferko_free(ctx, s);
        skgl__set_log(ctx, "skgl_shadow_analyze: RGBA32F targets not renderable", NULL);
        return SK_ERR_GL;
    }
    skgl__ferko_poll(ctx, st, s);
    skgl__timer_begin(ctx, &s->t_analyze);
    skgl__st_screen_pass(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    /* level 0: 4x4 blocks of the G-buffer */
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->ferko.fbo[0]);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, s->ferko.lw[0], s->ferko.lh[0]);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->ferko_prog);
    skgl__st_texture(ctx, st, 1, SKGL__T_2D, depth_tex, ctx->point_sampler);
    skgl__depth_map_send(gl, ctx->ferko_u_depth_map, ctx->ferko_dmap, ctx->cam_dmap);
    ndc_to_light = sk_mat4_mul(*lvp, *inv);
    world_w[0] = inv->m[3]; world_w[1] = inv->m[7]; world_w[2] = inv->m[11]; world_w[3] = inv->m[15];
    gl->UniformMatrix4fv(ctx->ferko_u_ndc_to_light, 1, 0, ndc_to_light.m);
    gl->Uniform4fv(ctx->ferko_u_world_w, 1, world_w);
    if (ctx->ferko_depth_only != (s->desc.technique != SKGL_FERKO)) {
        /* AUTO and .fit_to_depth read only the depth range: no patches */
        ctx->ferko_depth_only = s->desc.technique != SKGL_FERKO;
        skgl__u1i(gl, ctx->ferko_u_depth_only, ctx->ferko_depth_only);
    }
    if (memcmp(ctx->ferko_view_z, ctx->cam_view_z, sizeof ctx->ferko_view_z) != 0) {   /* a new projection */
        memcpy(ctx->ferko_view_z, ctx->cam_view_z, sizeof ctx->ferko_view_z);
        gl->Uniform4fv(ctx->ferko_u_view_z, 1, ctx->cam_view_z);
    }
    gl->DrawArrays(SKGL__TRIANGLES, 0, 3);
    /* 16x16 MIN reductions (the source level on unit 1's 2D-array target),
       then the final pass over what is left into the 2x1 texels */
    for (k = 1; k <= s->ferko.levels; k++) {
        int fin = k == s->ferko.levels, src = k - 1;
        int *cache = fin ? ctx->final_src : ctx->reduce_src;
        skgl__int loc = fin ? ctx->final_u_src_size : ctx->reduce_u_src_size;
        if (fin) {
            skgl__st_framebuffer(ctx, st, s->ferko.final_fbo);   /* read back from it too */
            skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, 2, 1);
        } else {
            skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->ferko.fbo[skgl__ferko_slot(k)]);
            skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, s->ferko.lw[k], s->ferko.lh[k]);
        }
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)(fin ? ctx->final_prog : ctx->reduce_prog));
        skgl__st_set1(ctx, st, SKGL__S_TEX(1, SKGL__T_2D_ARRAY), (skgl__int)s->ferko.tex[skgl__ferko_slot(src)]);
        if (cache[0] != s->ferko.lw[src] || cache[1] != s->ferko.lh[src]) {
            cache[0] = s->ferko.lw[src];
            cache[1] = s->ferko.lh[src];
            if (loc >= 0) gl->Uniform2i(loc, cache[0], cache[1]);
        }
        gl->DrawArrays(SKGL__TRIANGLES, 0, 3);
    }
    if (sync) {
        /* this frame's estimate: the read-back waits for the GPU */
        skgl__st_pack(ctx, st, 0, 1, 32);
        gl->ReadPixels(0, 0, 2, 1, SKGL__RGBA, SKGL__FLOAT, v);
        skgl__ferko_land(s, v, lvp, o);
    } else if ((slot = skgl__ring_slot(ctx, st, &s->ferko.ring)) >= 0) {
        /* with a pixel pack buffer bound, glReadPixels' pointer is an
           offset into it, and the call returns without waiting */
        skgl__st_pack(ctx, st, s->ferko.ring.buf[slot], 1, 32);
        gl->ReadPixels(0, 0, 2, 1, SKGL__RGBA, SKGL__FLOAT, (void *)0);
        s->ferko.ring.lvp[slot] = *lvp;
        memcpy(s->ferko.ring.origin[slot], o, sizeof s->ferko.ring.origin[slot]);
        skgl__ring_fence(ctx, &s->ferko.ring, slot);
    }
    skgl__timer_end(ctx, &s->t_analyze);
    s->stats.analysis_ms = s->t_analyze.ms;
    return SK_OK;
}

/* SKGL_AUTO's analysis is run again when the view depths it measured may
   have changed (CHOOSING FOR YOU): before the first, when the G-buffer's
   size or the camera's projection changed, when the camera moved more than
   5% of the nearest depth measured (half the 10% margin skgl__depth_fit
   widens the range by; the other half covers the read-back's latency) or
   turned more than about 1.7 degrees (a rotation element changed by more
   than 0.03), and every SKGL__AUTO_KEEP + 1 frames whatever the camera did
   (objects that move). Otherwise the last range is kept: no GL work. */
#define SKGL__AUTO_KEEP 7
static int skgl__auto_stale(const skgl_shadow *s, const skgl_camera *cam, int w, int h)
{
    double reach = 0.05 * (double)s->ferko.depth_lo, e0[3], e1[3];
    if (s->ferko.state == 0 || s->auto_kept >= SKGL__AUTO_KEEP || s->ferko.w != w || s->ferko.h != h ||
        !(s->ferko.depth_hi > 0.0f) || memcmp(&cam->proj, &s->auto_proj, sizeof cam->proj) != 0)
        return 1;
    if (skgl__view_turned(&cam->view, &s->auto_view, 0.03f)) return 1;
    skgl__view_eye(&cam->view, e0);
    skgl__view_eye(&s->auto_view, e1);
    return !(skgl__dist2(e0, e1) <= reach * reach);
}

/* AUTO: FERKO's analysis (its depth range only) when skgl__auto_stale says
   so, else the ring polled and the last range kept */
static sk_result skgl__analyze_auto(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_camera *cam,
                                    const sk_mat4 *inv, const sk_mat4 *lvp, const double o[3], unsigned depth_tex,
                                    int w, int h)
{
    sk_result r;
    if (!skgl__auto_stale(s, cam, w, h)) {
        skgl__ferko_poll(ctx, st, s);
        s->auto_kept++;
        s->stats.auto_analysed = 0;
        s->stats.analysis_ms = 0.0f;
        return SK_OK;
    }
    r = skgl__analyze_ferko(ctx, st, s, cam, inv, lvp, o, depth_tex, w, h);
    if (r != SK_OK) return r;
    s->auto_view = cam->view;
    s->auto_proj = cam->proj;
    s->auto_kept = 0;
    s->stats.auto_analysed = 1;
    return SK_OK;
}
#endif /* SKGL_NO_FERKO */

/* ---- 6.4 RMSM: virtual shadow map pages (Romanick's VGP353 notes) ---- */
#ifndef SKGL_NO_RMSM
// >>rmsm
/* the bytes of one read-back of rmsm.requests */
static size_t skgl__rmsm_req_bytes(const skgl_shadow *s)
{
    return (size_t)s->rmsm.atlas_w * (size_t)s->rmsm.atlas_h * (s->rmsm.req_fmt == SKGL__RGBA ? 4u : 1u);
}

/* the request atlas (R8) and the page table (RGBA8): every level's page grid
   side by side, level l (n_l = pages0 >> l pages a side) from column
   2 pages0 - 2 n_l; the table starts all 0 (nothing resident). The
   requests are that atlas, in R8 with desc.rmsm_band_pages -1, else in RGBA8
   with the levels each level-0 page's samples ask for (rmsm_request.vert). */
static sk_result skgl__rmsm_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    int cap = s->desc.rmsm_pool_pages * s->desc.rmsm_pool_pages;
    size_t bytes;
    SKGL__TRY(skgl__rmsm_programs(ctx, st));
    s->rmsm.pages0 = s->desc.resolution / s->desc.rmsm_page_size;
    for (s->rmsm.levels = 1; (1 << (s->rmsm.levels - 1)) < s->rmsm.pages0; s->rmsm.levels++) {}
    s->rmsm.atlas_w = 2 * s->rmsm.pages0 - 1;
    s->rmsm.atlas_h = s->rmsm.pages0;
    s->rmsm.bands = s->desc.rmsm_band_pages < 0 ? 1 : s->rmsm.levels;
    s->rmsm.req_fmt = s->rmsm.bands > 1 ? SKGL__RGBA : SKGL__RED;
    bytes = (size_t)s->rmsm.atlas_w * (size_t)s->rmsm.atlas_h;
    s->rmsm.req_cpu = (unsigned char *)SKGL_MALLOC(skgl__rmsm_req_bytes(s));
    s->rmsm.mark = (unsigned char *)SKGL_MALLOC(bytes);
    s->rmsm.table_cpu = (unsigned char *)SKGL_MALLOC(4 * bytes);
    s->rmsm.table_new = (unsigned char *)SKGL_MALLOC(4 * bytes);
    s->rmsm.pages = (sk_page *)SKGL_MALLOC(sizeof(sk_page) * (size_t)cap);
    s->rmsm.slot_of = (int *)SKGL_MALLOC(sizeof(int) * (size_t)cap);
    if (!s->rmsm.req_cpu || !s->rmsm.mark || !s->rmsm.table_cpu || !s->rmsm.table_new || !s->rmsm.pages ||
        !s->rmsm.slot_of)
        return SK_ERR_CAPACITY;
    memset(s->rmsm.table_cpu, 0, 4 * bytes);
    if (s->desc.cache) {   /* the page cache: every slot empty, everything to draw */
        s->rmsm.slots = (skgl__rmsm_slot *)SKGL_MALLOC(sizeof(skgl__rmsm_slot) * (size_t)cap);
        s->rmsm.resident = (int *)SKGL_MALLOC(sizeof(int) * bytes);
        s->rmsm.lru = (skgl__lru *)SKGL_MALLOC(sizeof(skgl__lru) * (size_t)cap);
        if (!s->rmsm.slots || !s->rmsm.resident || !s->rmsm.lru) return SK_ERR_CAPACITY;
        memset(s->rmsm.slots, 0, sizeof(skgl__rmsm_slot) * (size_t)cap);
        memset(s->rmsm.resident, 0, sizeof(int) * bytes);
        s->cache.all = 1;
        s->cache.layers = s->stats.cache_layers = 1;
        s->stats.cache_verify_texels = -1;
    }
    s->rmsm.requests = skgl__color_texture(ctx, st, s->rmsm.bands > 1 ? SKGL__RGBA8 : SKGL__R8, s->rmsm.atlas_w,
                                           s->rmsm.atlas_h, 1, s->rmsm.req_fmt, SKGL__UNSIGNED_BYTE, NULL);
    s->rmsm.table = skgl__color_texture(ctx, st, SKGL__RGBA8, s->rmsm.atlas_w, s->rmsm.atlas_h, 1, SKGL__RGBA,
                                        SKGL__UNSIGNED_BYTE, s->rmsm.table_cpu);
    s->rmsm.requests_fbo = skgl__framebuffer(ctx, st, s->rmsm.requests, 1, 0, 0);
    skgl__ring_create(ctx, st, &s->rmsm.ring, skgl__rmsm_req_bytes(s));
    {
        int slot = s->desc.rmsm_page_size + 2;
        sk_result r = skgl__verify_texture(ctx, st, &s->rmsm.page_tex, &s->rmsm.page_fbo, slot, slot,
                                           "skgl_shadow_create");
        if (r != SK_OK) return r;
    }
    if (!s->rmsm.requests_fbo) {
        skgl__set_log(ctx, "skgl_shadow_create: the RMSM request atlas (R8) is not renderable", NULL);
        return SK_ERR_GL;
    }
    return SK_OK;
}

/* the batch target's objects (desc.layered) */
static void skgl__rmsm_batch_free(skgl_context *ctx, skgl_shadow *s)
{
    int i;
    skgl__delete_framebuffer(ctx, &s->rmsm.batch_fbo);
    for (i = 0; i < SKGL_MAX_CASCADES; i++) skgl__delete_framebuffer(ctx, &s->rmsm.batch_layer_fbo[i]);
    skgl__delete_texture(ctx, &s->rmsm.batch_tex);
}

/* 1 when this light's pages can be drawn SKGL_MAX_CASCADES at a pass
   (desc.layered): the layered program and the batch target, made now if
   need be; 0 keeps a pass per page (no geometry shader program, or the
   target not renderable: tried once) */
static int skgl__rmsm_batch_ready(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    skgl__rmsm *m = &s->rmsm;
    int slot = s->desc.rmsm_page_size + 2, i, ok;
    if (m->batch_state != 0) return m->batch_state > 0;
    m->batch_state = -1;
    if (!skgl__layered_ready(ctx)) return 0;
    ctx->gl.GenTextures(1, &m->batch_tex);
    ctx->objects++;
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY), (skgl__int)m->batch_tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    ctx->gl.TexImage3D(SKGL__TEXTURE_2D_ARRAY, 0, SKGL__DEPTH_COMPONENT32F, slot, slot, SKGL_MAX_CASCADES, 0,
                       SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    ctx->gl.TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST);
    ctx->gl.TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MAG_FILTER, SKGL__NEAREST);
    m->batch_fbo = skgl__framebuffer(ctx, st, 0, 0, m->batch_tex, SKGL__ALL_LAYERS);
    for (i = 0, ok = m->batch_fbo != 0; ok && i < SKGL_MAX_CASCADES; i++)
        ok = (m->batch_layer_fbo[i] = skgl__framebuffer(ctx, st, 0, 0, m->batch_tex, i)) != 0;
    if (!ok) {
        skgl__rmsm_batch_free(ctx, s);
        return 0;
    }
    m->batch_state = 1;
    return 1;
}

static void skgl__rmsm_free(skgl_context *ctx, skgl_shadow *s)
{
    skgl__delete_texture(ctx, &s->rmsm.samples);
    skgl__delete_texture(ctx, &s->rmsm.requests);
    skgl__delete_texture(ctx, &s->rmsm.table);
    skgl__delete_framebuffer(ctx, &s->rmsm.samples_fbo);
    skgl__delete_framebuffer(ctx, &s->rmsm.requests_fbo);
    skgl__delete_texture(ctx, &s->rmsm.page_tex);
    skgl__delete_framebuffer(ctx, &s->rmsm.page_fbo);
    skgl__rmsm_batch_free(ctx, s);
    skgl__ring_free(ctx, &s->rmsm.ring);
    SKGL_FREE(s->rmsm.req_cpu);
    SKGL_FREE(s->rmsm.mark);
    SKGL_FREE(s->rmsm.table_cpu);
    SKGL_FREE(s->rmsm.table_new);
    SKGL_FREE(s->rmsm.pages);
    SKGL_FREE(s->rmsm.slot_of);
    SKGL_FREE(s->rmsm.slots);
    SKGL_FREE(s->rmsm.resident);
    SKGL_FREE(s->rmsm.lru);
    s->rmsm.req_cpu = s->rmsm.mark = NULL;
    s->rmsm.table_cpu = s->rmsm.table_new = NULL;
    s->rmsm.pages = NULL;
    s->rmsm.slot_of = NULL;
    s->rmsm.slots = NULL;
    s->rmsm.resident = NULL;
    s->rmsm.lru = NULL;
}

/* texel index of page (level, px, py) in the request atlas and the page
   table (level l's n_l pages a side from column 2 pages0 - 2 n_l) */
static size_t skgl__atlas_index(const skgl_shadow *s, int level, int px, int py)
{
    int n = s->rmsm.pages0 >> level;
    return (size_t)py * (size_t)s->rmsm.atlas_w + (size_t)(2 * s->rmsm.pages0 - 2 * n + px);
}

/* pages some pixel asks for in one request atlas, from level l0 up */
static int skgl__rmsm_count(const skgl_shadow *s, const unsigned char *req, int l0)
{
    int count = 0, l, px, py;
    for (l = l0; l < s->rmsm.levels; l++)
        for (py = 0; py < (s->rmsm.pages0 >> l); py++)
            for (px = 0; px < (s->rmsm.pages0 >> l); px++) count += req[skgl__atlas_index(s, l, px, py)] != 0;
    return count;
}

/* the level request band b asks for where the pixel-matched one is f
   (rmsm_request.vert): band 0 f; band b > 0 at most top - b (the cap on
   the texel's world size), one level finer than f where finer is set,
   and never below floor_level */
static int skgl__band_level(int f, int b, int finer, int floor_level, int top)
{
    if (b == 0) return f;
    if (finer && f > 0) f--;
    if (f > top - b) f = top - b;
    return f > floor_level ? f : floor_level;
}

/* Band b > 0's pages, from the banded atlas's level-0 texels (red and
   green: the least and 254 - the greatest pixel-matched level of the
   page's samples; 255 in red: none): a sample asks for the ancestor of
   its level-0 page at its band level, so the page asks for its ancestors
   at the band levels of [fmin, fmax] (every one between: a superset where
   the levels present skip one; skgl__band_level with finer and
   floor_level). Each is marked in rmsm.mark with stamp; their count,
   which stops past stop (a band that cannot fit). */
static int skgl__rmsm_band_mark(skgl_shadow *s, const unsigned char *atlas, int b, int finer, int floor_level,
                                unsigned char stamp, int stop)
{
    int n0 = s->rmsm.pages0, top = s->rmsm.levels - 1, count = 0, px, py, l;
    for (py = 0; py < n0; py++)
        for (px = 0; px < n0; px++) {
            const unsigned char *e = atlas + 4 * skgl__atlas_index(s, 0, px, py);
            int lo, hi;
            if (e[0] == 255) continue;
            lo = skgl__band_level(e[0], b, finer, floor_level, top);
            hi = skgl__band_level(254 - e[1], b, finer, floor_level, top);
            for (l = lo; l <= hi; l++) {
                unsigned char *m = &s->rmsm.mark[skgl__atlas_index(s, l, px >> l, py >> l)];
                if (*m == stamp) continue;
                *m = stamp;
                if (++count > stop) return count;
            }
        }
    return count;
}

/* The finest cap on the texel's world size whose band fits in cap slots
   with the coarsest page, at floor floor_level: for each cap from the
   finest (top - b, b = top - floor_level first), its pages one level finer
   than the pixel, else the cap alone (the pixel-matched level under it).
   Returns the band (0: none fits), *finer and *stamp (rmsm.mark's). */
static int skgl__rmsm_band_fit(skgl_shadow *s, const unsigned char *atlas, int cap, int floor_level, int *finer,
                               unsigned char *stamp)
{
    int top = s->rmsm.bands - 1, b, k;
    for (b = top - floor_level; b > 0; b--)
        for (k = 1; k >= 0; k--) {
            ++*stamp;
            if (skgl__rmsm_band_mark(s, atlas, b, k, floor_level, *stamp, cap - 1) + 1 <= cap) {
                *finer = k;
                return b;
            }
        }
    return 0;
}

/* The banded requests (desc.rmsm_band_pages >= 0) as one request atlas in
   rmsm.mark (nonzero: asked for): the band with the finest cap on the
   texel's world size that fits in the pool with the coarsest page, its
   pages a level finer than the pixel where that fits too
   (skgl__rmsm_band_fit); else band 0, the pixel-matched pages (blue 0 in
   the banded atlas, exactly those of the matched one). Lefohn, Sengupta
   and Owens match a texel to a pixel, which leaves a caster thinner than
   the pixel's footprint (a pole's shadow at 500 m) to the chance of
   covering a texel centre; the pool's spare slots buy, first, a cap on the
   texel's world size (the far field, where a pixel spans metres) and then
   texels of half a pixel. Where even the pixel-matched pages overflow the
   pool, the finest level rises (the floor, stats.rmsm_min_level) and the
   cap is sought again above it, rather than the far field left at the
   pixel-matched level. A band b > 0 fits in cap slots. */
static unsigned char *skgl__rmsm_bands(skgl_shadow *s, const unsigned char *atlas, int cap)
{
    size_t bytes = (size_t)s->rmsm.atlas_w * (size_t)s->rmsm.atlas_h, i;
    int b = 0, n = 0, finer = 0, floor_level, top = s->rmsm.bands - 1;
    int pool = s->desc.rmsm_pool_pages * s->desc.rmsm_pool_pages;
    unsigned char stamp = 0;
    for (i = 0; i < bytes; i++) n += atlas[4 * i + 2] != 255;
    s->stats.pages_requested = n;
    memset(s->rmsm.mark, 0, bytes);
    for (floor_level = 0; floor_level < top; floor_level++) {
        /* above a floor the pool is full either way, as the fold fills it
           (skgl__rmsm_pages): no half kept for a cache's earlier pages */
        b = skgl__rmsm_band_fit(s, atlas, floor_level > 0 ? pool : cap, floor_level, &finer, &stamp);
        if (b > 0 || n + 1 <= pool) break;
    }
    s->stats.rmsm_band = b;
    s->stats.rmsm_band_finer = b > 0 && finer;
    s->rmsm.floor_level = b > 0 ? floor_level : 0;
    if (b > 0)
        for (i = 0; i < bytes; i++) s->rmsm.mark[i] = s->rmsm.mark[i] == stamp;
    else
        for (i = 0; i < bytes; i++) s->rmsm.mark[i] = atlas[4 * i + 2] != 255;
    return s->rmsm.mark;
}

/* the slots a finer band may take (desc.rmsm_band_pages): a cached light
   keeps half the pool for the pages of earlier frames (skgl__rmsm_assign),
   which a band that filled it would evict */
static int skgl__rmsm_band_cap(const skgl_shadow *s)
{
    int cap = s->desc.rmsm_pool_pages * s->desc.rmsm_pool_pages;
    if (s->desc.rmsm_band_pages > 0) return s->desc.rmsm_band_pages;
    return s->desc.cache ? cap / 2 : cap;
}

/* The pages to render from the requests read back: the request atlas (a
   nonzero texel per page some pixel asks for, levels clamped to [0,
   levels - 1] as sk_rmsm_page_requests clamps them) with
   desc.rmsm_band_pages -1, else the banded atlas, whose band skgl__rmsm_bands
   picks. When they do not fit in the pool (with the coarsest page, always
   resident), the finest level rises: its requests fold into their parents
   one level up (page (px, py) of level l is inside (px/2, py/2) of level
   l + 1, the page a sample clamped to l + 1 would have asked for), until
   they fit. The list is sorted by (level, py, px), as
   sk_rmsm_page_requests sorts. The requests are folded in place. */
static void skgl__rmsm_pages(skgl_shadow *s, unsigned char *data)
{
    int cap = s->desc.rmsm_pool_pages * s->desc.rmsm_pool_pages, min_level = 0, count, l, px, py;
    int top = s->rmsm.levels - 1;
    unsigned char *req = data;
    s->stats.rmsm_band = s->stats.rmsm_band_finer = 0;
    s->rmsm.floor_level = 0;
    if (s->rmsm.bands > 1) req = skgl__rmsm_bands(s, data, skgl__rmsm_band_cap(s));
    else s->stats.pages_requested = skgl__rmsm_count(s, req, 0);
    min_level = s->rmsm.floor_level;
    count = skgl__rmsm_count(s, req, min_level);
    while (count + 1 > cap && min_level < top) {
        int n = s->rmsm.pages0 >> min_level;
        for (py = 0; py < n; py++)
            for (px = 0; px < n; px++)
                if (req[skgl__atlas_index(s, min_level, px, py)])
                    req[skgl__atlas_index(s, min_level + 1, px / 2, py / 2)] = 1;
        min_level++;
        count = skgl__rmsm_count(s, req, min_level);
    }
    s->rmsm.npages = 0;
    for (l = min_level; l < s->rmsm.levels; l++)
        for (py = 0; py < (s->rmsm.pages0 >> l); py++)
            for (px = 0; px < (s->rmsm.pages0 >> l); px++)
                if ((req[skgl__atlas_index(s, l, px, py)] != 0 || l == top) && s->rmsm.npages < cap) {
                    s->rmsm.pages[s->rmsm.npages].level = l;
                    s->rmsm.pages[s->rmsm.npages].px = px;
                    s->rmsm.pages[s->rmsm.npages].py = py;
                    s->rmsm.npages++;
                }
    s->stats.rmsm_min_level = min_level;
}

/* The page table of this frame's pages (page i in slot k = slot_of[i], at
   (k % pool, k / pool) of the pool),
   and only its rows that differ from the table GL has uploaded: one
   glTexSubImage2D over the first to the last changed row, none when the
   pages are those of the last frame. Bound on unit 0 to upload. */
static void skgl__rmsm_table(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    size_t row = (size_t)4 * (size_t)s->rmsm.atlas_w;
    int i, pool = s->desc.rmsm_pool_pages, r0 = -1, r1 = -1, y;
    memset(s->rmsm.table_new, 0, row * (size_t)s->rmsm.atlas_h);
    for (i = 0; i < s->rmsm.npages; i++) {
        unsigned char *e = s->rmsm.table_new + 4 * skgl__atlas_index(s, s->rmsm.pages[i].level, s->rmsm.pages[i].px,
                                                                    s->rmsm.pages[i].py);
        e[0] = (unsigned char)(s->rmsm.slot_of[i] % pool);
        e[1] = (unsigned char)(s->rmsm.slot_of[i] / pool);
        e[3] = 255;
    }
    for (y = 0; y < s->rmsm.atlas_h; y++)
        if (memcmp(s->rmsm.table_new + row * (size_t)y, s->rmsm.table_cpu + row * (size_t)y, row) != 0) {
            if (r0 < 0) r0 = y;
            r1 = y;
        }
    if (r0 < 0) return;
    memcpy(s->rmsm.table_cpu + row * (size_t)r0, s->rmsm.table_new + row * (size_t)r0, row * (size_t)(r1 - r0 + 1));
    skgl__st_unpack(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D), (skgl__int)s->rmsm.table);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D));
    ctx->gl.TexSubImage2D(SKGL__TEXTURE_2D, 0, 0, r0, s->rmsm.atlas_w, r1 - r0 + 1, SKGL__RGBA, SKGL__UNSIGNED_BYTE,
                          s->rmsm.table_cpu + row * (size_t)r0);
}

/* RMSM analysis: per-pixel samples, page requests scattered on the GPU into
   the request atlas, read back; the pages (the next render lays them out
   in the pool and uploads the table) from the requests of the last frame
   (ring) or, with sync_readback and on the first analysis, of this one (a
   read-back that waits for the GPU). lvp is the virtual map's frustum
   (skgl__rmsm_frame) relative to o. */
static sk_result skgl__analyze_rmsm(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_camera *cam,
                                    const sk_mat4 *inv, const sk_mat4 *lvp, const double o[3], unsigned depth_tex,
                                    int w, int h)
{
    skgl__api *gl = &ctx->gl;
    static const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f}, one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    int sync = s->desc.sync_readback || !s->rmsm.analyzed, slot, banded = s->rmsm.bands > 1;
    (void)cam;
    (void)o;   /* lvp and inv are relative to it already; the render places the pages itself */
    if (s->rmsm.w != w || s->rmsm.h != h) {
        skgl__delete_texture(ctx, &s->rmsm.samples);
        skgl__delete_framebuffer(ctx, &s->rmsm.samples_fbo);
        s->rmsm.samples = skgl__color_texture(ctx, st, SKGL__RGBA32F, w, h, 1, SKGL__RGBA, SKGL__FLOAT, NULL);
        s->rmsm.samples_fbo = skgl__framebuffer(ctx, st, s->rmsm.samples, 1, 0, 0);
        s->rmsm.w = s->rmsm.samples_fbo ? w : 0;
        s->rmsm.h = s->rmsm.samples_fbo ? h : 0;
        if (!s->rmsm.samples_fbo) {
            skgl__set_log(ctx, "skgl_shadow_analyze: RGBA32F target not renderable", NULL);
            return SK_ERR_GL;
        }
    }
    /* last frame's requests, if they have landed */
    if (!sync && (slot = skgl__ring_poll(ctx, st, &s->rmsm.ring, s->rmsm.req_cpu)) >= 0) {
        skgl__rmsm_pages(s, s->rmsm.req_cpu);
    }
    skgl__timer_begin(ctx, &s->t_analyze);
    skgl__st_screen_pass(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    /* the samples: one per pixel */
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->rmsm.samples_fbo);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, w, h);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->rmsm_prog);
    skgl__st_texture(ctx, st, 1, SKGL__T_2D, depth_tex, ctx->point_sampler);
    skgl__depth_map_send(gl, ctx->rmsm_u_depth_map, ctx->rmsm_dmap, ctx->cam_dmap);
    gl->UniformMatrix4fv(ctx->rmsm_u_inv_view_proj, 1, 0, inv->m);
    gl->UniformMatrix4fv(ctx->rmsm_u_light, 1, 0, lvp->m);
    if (ctx->rmsm_vres != (float)s->desc.resolution) {
        ctx->rmsm_vres = (float)s->desc.resolution;
        skgl__u1f(gl, ctx->rmsm_u_virtual_res, ctx->rmsm_vres);
    }
    gl->DrawArrays(SKGL__TRIANGLES, 0, 3);
    /* the requests: a point per sample onto its page's texel; banded, two:
       one there (blue 0) and one onto its level-0 page ((f, 254 - f) in
       red and green), the least of each kept (blending MIN, from the
       clear's 255: none) */
    skgl__st_framebuffer(ctx, st, s->rmsm.requests_fbo);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, s->rmsm.atlas_w, s->rmsm.atlas_h);
    gl->ClearBufferfv(SKGL__COLOR, 0, banded ? one : zero);
    if (banded) {
        skgl__st_set1(ctx, st, SKGL__S_BLEND, 1);
        skgl__st_set4(ctx, st, SKGL__S_BLEND_EQ, SKGL__MIN, SKGL__MIN, 0, 0);
        skgl__st_set4(ctx, st, SKGL__S_BLEND_FUNC, SKGL__ONE, SKGL__ONE, SKGL__ONE, SKGL__ONE);
    }
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->request_prog);
    if (ctx->request_pages0 != s->rmsm.pages0 || ctx->request_levels != s->rmsm.levels) {
        ctx->request_pages0 = s->rmsm.pages0;
        ctx->request_levels = s->rmsm.levels;
        skgl__u1i(gl, ctx->request_u_pages0, s->rmsm.pages0);
        skgl__u1i(gl, ctx->request_u_levels, s->rmsm.levels);
    }
    if (ctx->request_bands != s->rmsm.bands) {
        ctx->request_bands = s->rmsm.bands;
        skgl__u1i(gl, ctx->request_u_bands, s->rmsm.bands);
    }
    skgl__st_texture(ctx, st, 1, SKGL__T_2D, s->rmsm.samples, ctx->point_sampler);
    /* the vertex shader's gl_PointSize, not the glPointSize the caller set */
    skgl__st_set1(ctx, st, SKGL__S_POINT_SIZE, 1);
    gl->DrawArrays(SKGL__POINTS, 0, w * h * (banded ? 2 : 1));
    skgl__st_set1(ctx, st, SKGL__S_BLEND, 0);
    if (sync) {
        /* this frame's requests: the read-back waits for the GPU. A byte
           a texel (GL_RED of the R8 atlas): rows of atlas_w bytes, hence
           the pack alignment of 1 (the default 4 would pad them) */
        skgl__st_pack(ctx, st, 0, s->rmsm.atlas_h, (int)(skgl__rmsm_req_bytes(s) / (size_t)s->rmsm.atlas_h));
        gl->ReadPixels(0, 0, s->rmsm.atlas_w, s->rmsm.atlas_h, (skgl__enum)s->rmsm.req_fmt, SKGL__UNSIGNED_BYTE,
                       s->rmsm.req_cpu);
        skgl__rmsm_pages(s, s->rmsm.req_cpu);
    } else if ((slot = skgl__ring_slot(ctx, st, &s->rmsm.ring)) >= 0) {
        skgl__st_pack(ctx, st, s->rmsm.ring.buf[slot], s->rmsm.atlas_h,
                      (int)(skgl__rmsm_req_bytes(s) / (size_t)s->rmsm.atlas_h));
        gl->ReadPixels(0, 0, s->rmsm.atlas_w, s->rmsm.atlas_h, (skgl__enum)s->rmsm.req_fmt, SKGL__UNSIGNED_BYTE,
                       (void *)0);
        skgl__ring_fence(ctx, &s->rmsm.ring, slot);
    }
    s->rmsm.analyzed = 1;
    skgl__timer_end(ctx, &s->t_analyze);
    s->stats.analysis_ms = s->t_analyze.ms;
    return SK_OK;
}

/* RMSM's virtual map: the uncropped light frustum around the scene's
   bounds (skgl__ferko_light), relative to the bounds' centre rounded to
   SKGL_ORIGIN_CELL (o). It depends on the bounds and the light alone, not
   on the camera: the pages' texel grid is fixed in light space, and a page
   drawn in an earlier frame holds this frame's texels. */
static sk_result skgl__rmsm_frame(const sk_aabb *world, sk_vec3 light_dir, sk_mat4 *lvp, double o[3])
{
    const double cell = SKGL_ORIGIN_CELL;
    double c[3];
    skgl_scene rel;
    int k;
    c[0] = 0.5 * ((double)world->min.x + world->max.x);
    c[1] = 0.5 * ((double)world->min.y + world->max.y);
    c[2] = 0.5 * ((double)world->min.z + world->max.z);
    for (k = 0; k < 3; k++) {
        o[k] = cell > 0.0 ? SK_FLOOR(c[k] / cell + 0.5) * cell : 0.0;
        if (!(SK_FABS(o[k]) < 1e30)) o[k] = 0.0;
    }
    memset(&rel, 0, sizeof rel);
    rel.bounds = *world;
    rel = skgl__scene_rel(&rel, o);
    return skgl__ferko_light(&rel, light_dir, lvp);
}

/* the analysis's light frustum: the virtual map's, whose page grid is
   fixed in the world (skgl__rmsm_frame), moved to o */
static sk_result skgl__rmsm_analysis_frame(const skgl_scene *scene, const skgl_scene *rs, sk_vec3 light_dir,
                                           const double o[3], sk_mat4 *lvp)
{
    sk_mat4 vlvp;
    double vo[3];
    sk_result r = skgl__rmsm_frame(&scene->bounds, light_dir, &vlvp, vo);
    (void)rs;
    *lvp = skgl__shift(&vlvp, vo, o);
    return r;
}

/* skgl_shadow_bind: the page table on unit + 1 (point sampled) */
static skgl__int skgl__rmsm_bind(skgl_context *ctx, const skgl_shadow *s, int unit)
{
    skgl__api *gl = &ctx->gl;
    gl->ActiveTexture((skgl__enum)(SKGL__TEXTURE0 + unit + 1));
    gl->BindTexture(SKGL__TEXTURE_2D, s->rmsm.table);
    gl->BindSampler((skgl__uint)unit + 1, ctx->point_sampler);
    return SKGL__TEXTURE0 + unit + 1;
}

/* skgl_shadow_mask: the page table on unit 3 */
static int skgl__rmsm_mask(const skgl_shadow *s, skgl__unitbind *b)
{
    skgl__bind_unit(b, 3, SKGL__T_2D, s->rmsm.table, 0);
    return 1;
}
#endif /* SKGL_NO_RMSM */

/* ---- 6.5 the cache: static casters kept from frame to frame ----------- */
// >>cache
/* CACHED MAPS. The cache holds, per cached layer, the depth of scene.draw's
   casters and the world -> light clip matrix that depth stands for: the
   one it was drawn with, moved by the whole texels it was scrolled since.
   Each render compares the layer's new matrix with that one, never with
   last frame's, so changes too small to see one frame at a time (a sun
   turning 5e-7 rad a frame, a camera creeping under a focused crop) add
   up until the layer is drawn again: the same map (within float rounding,
   skgl__cache_shift) is reused; an orthographic map moved by whole texels
   in x and y, nothing else changed (a stable crop following the camera),
   is scrolled: the overlap copied, only the strips it exposes drawn; any
   other change (the light turned, the scene's bounds, a warp that follows
   the camera) draws the layer whole. Every pass into a kept layer (the
   strips, invalidated regions, the dynamic casters) uses the layer's own
   matrix, so the layer is one map of one matrix, within the tolerance of
   this frame's; the lookup uses this frame's. Invalidated boxes are drawn
   again in the rectangles their corners cover. The map the shaders sample
   is the cache plus the dynamic casters (skgl_set_dynamic), drawn over a
   copy each frame; without dynamic casters the copy is made only when the
   cache changed. */
#ifndef SKGL_NO_CACHE

/* world -> light clip of a matrix that takes p - o, in double */
static void skgl__world_matrix(const sk_mat4 *m, const double o[3], double w[16])
{
    int k;
    for (k = 0; k < 12; k++) w[k] = m->m[k];
    for (k = 0; k < 4; k++)
        w[12 + k] = (double)m->m[12 + k] - ((double)m->m[k] * o[0] + (double)m->m[4 + k] * o[1] +
                                            (double)m->m[8 + k] * o[2]);
}

/* the matrix taking p - o of a world -> light clip one (skgl__world_matrix's inverse) */
static sk_mat4 skgl__origin_matrix(const double w[16], const double o[3])
{
    sk_mat4 m;
    int k;
    for (k = 0; k < 12; k++) m.m[k] = (float)w[k];
    for (k = 0; k < 4; k++) m.m[12 + k] = (float)(w[12 + k] + w[k] * o[0] + w[4 + k] * o[1] + w[8 + k] * o[2]);
    return m;
}

/* 1 when `now` is `was` moved by whole texels (*dx, *dy; 0 0: the same
   map) of a res x res map; 0 when the layer must be drawn whole. `was` is
   the matrix the layer's depth stands for, not last frame's: the
   tolerances bound how far the kept layer is from this frame's map,
   however many frames it is kept. Only an orthographic map's content
   moves by a translation of its x and y: a perspective one must match in
   every entry. The tolerances are float's: a stable crop's scale is
   2 / (right - left) of two floats that move with the crop, so it changes
   in its last bit from frame to frame; a change that moves no point of
   the map by more than 1e-3 texel is taken as none (the linear entries
   within 1e-3 / res of the largest, the shift within 1e-3 texel of a
   whole one, depth within 1e-6). */
static int skgl__cache_shift(const double *was, const double *now, int res, int *dx, int *dy)
{
    int k, ortho = was[3] == 0.0 && was[7] == 0.0 && was[11] == 0.0 && was[15] == 1.0;
    double fx = (now[12] - was[12]) * 0.5 * res, fy = (now[13] - was[13]) * 0.5 * res, big = 0.0;
    for (k = 0; k < 12; k++) if (SK_FABS(was[k]) > big) big = SK_FABS(was[k]);
    for (k = 0; k < 16; k++) {
        double tol = k >= 12 ? 1e-6 : 1e-3 / res * big;
        if ((ortho && (k == 12 || k == 13)) || SK_FABS(now[k] - was[k]) <= tol) continue;
        return 0;
    }
    *dx = (int)SK_FLOOR(fx + 0.5);
    *dy = (int)SK_FLOOR(fy + 0.5);
    return SK_FABS(fx - *dx) <= 1e-3 && SK_FABS(fy - *dy) <= 1e-3;
}

/* the texel rectangle (x, y, w, h) of a res x res map that a world box's
   shadow may touch: its corners' bounds, one texel wider each side (the
   rasteriser's rounding); the whole map when a corner is behind a
   perspective map's eye. 0: the box misses the map (all its corners
   outside one clip plane). */
static int skgl__cache_box_rect(const double *w, const sk_aabb *box, int res, int rect[4])
{
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, cl[8][4];
    int i, k, all_out = 0x3f, behind = 0;
    for (i = 0; i < 8; i++) {
        sk_vec3 c = sk__aabb_corner(box, i);
        int out = 0;
        for (k = 0; k < 4; k++) cl[i][k] = w[k] * c.x + w[4 + k] * c.y + w[8 + k] * c.z + w[12 + k];
        out |= (cl[i][0] < -cl[i][3]) | (cl[i][0] > cl[i][3]) << 1 | (cl[i][1] < -cl[i][3]) << 2 |
               (cl[i][1] > cl[i][3]) << 3 | (cl[i][2] < -cl[i][3]) << 4 | (cl[i][2] > cl[i][3]) << 5;
        all_out &= out;
        behind |= !(cl[i][3] > 1e-12);
    }
    if (all_out) return 0;
    if (behind) { rect[0] = rect[1] = 0; rect[2] = rect[3] = res; return 1; }
    for (i = 0; i < 8; i++) {
        double cx = cl[i][0] / cl[i][3], cy = cl[i][1] / cl[i][3];
        if (cx < x0) x0 = cx;
        if (cx > x1) x1 = cx;
        if (cy < y0) y0 = cy;
        if (cy > y1) y1 = cy;
    }
    x0 = SK_FLOOR((x0 + 1.0) * 0.5 * res) - 1.0; x1 = SK_CEIL((x1 + 1.0) * 0.5 * res) + 1.0;
    y0 = SK_FLOOR((y0 + 1.0) * 0.5 * res) - 1.0; y1 = SK_CEIL((y1 + 1.0) * 0.5 * res) + 1.0;
    if (x0 < 0.0) x0 = 0.0;
    if (y0 < 0.0) y0 = 0.0;
    if (x1 > res) x1 = res;
    if (y1 > res) y1 = res;
    if (!(x1 > x0) || !(y1 > y0)) return 0;
    rect[0] = (int)x0; rect[1] = (int)y0; rect[2] = (int)(x1 - x0); rect[3] = (int)(y1 - y0);
    return 1;
}

/* The rectangles of a res x res map to draw again for n invalidated
   boxes: each box's (skgl__cache_box_rect), or their bounding rectangle
   once when that is no larger than their areas added up (overlapping
   boxes, a caster's old and new place). Returns how many, into out. */
static int skgl__dirty_rects(const double *w, const sk_aabb *dirty, int n, int res, int out[][4])
{
    int k, m = 0, u[4] = {0, 0, 0, 0};
    double sum = 0.0;
    for (k = 0; k < n; k++) {
        int *r = out[m];
        if (!skgl__cache_box_rect(w, &dirty[k], res, r)) continue;
        sum += (double)r[2] * r[3];
        if (m == 0) memcpy(u, r, sizeof u);
        else {
            int x1 = u[0] + u[2] > r[0] + r[2] ? u[0] + u[2] : r[0] + r[2];
            int y1 = u[1] + u[3] > r[1] + r[3] ? u[1] + u[3] : r[1] + r[3];
            if (r[0] < u[0]) u[0] = r[0];
            if (r[1] < u[1]) u[1] = r[1];
            u[2] = x1 - u[0];
            u[3] = y1 - u[1];
        }
        m++;
    }
    if (m > 1 && (double)u[2] * u[3] <= sum) { memcpy(out[0], u, sizeof u); m = 1; }
    return m;
}

/* the cache's memory for n layers of a light */
static float skgl__minf(float a, float b) { return a < b ? a : b; }
static float skgl__maxf(float a, float b) { return a > b ? a : b; }

static double skgl__cache_layer_bytes(const skgl_shadow_desc *d) { return 4.0 * d->resolution * d->resolution; }

/* the cache's texture and a framebuffer per cached layer: the nearest
   layers that fit in cache_budget_kb (none fitting: no cache, the light
   draws every frame) */
static sk_result skgl__cache_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    skgl__api *gl = &ctx->gl;
    int i, n = s->layers;
    if (s->desc.cache_budget_kb > 0)
        while (n > 0 && n * skgl__cache_layer_bytes(&s->desc) > 1024.0 * s->desc.cache_budget_kb) n--;
    s->cache.layers = n;
    s->stats.cache_layers = n;
    s->stats.cache_bytes = n * skgl__cache_layer_bytes(&s->desc);
    s->stats.cache_verify_texels = -1;
    s->cache.all = 1;
    if (n == 0) return SK_OK;
    gl->GenTextures(1, &s->cache.tex);
    ctx->objects++;
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY), (skgl__int)s->cache.tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    gl->TexImage3D(SKGL__TEXTURE_2D_ARRAY, 0, SKGL__DEPTH_COMPONENT32F, s->tex_size, s->tex_size, n, 0,
                   SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MAG_FILTER, SKGL__NEAREST);
    for (i = 0; i < n; i++) {
        s->cache.fbo[i] = skgl__framebuffer(ctx, st, 0, 0, s->cache.tex, i);
        if (!s->cache.fbo[i]) {
            skgl__set_log(ctx, "skgl_shadow_create: cache framebuffer incomplete", NULL);
            return SK_ERR_GL;
        }
    }
    return SK_OK;
}

static void skgl__cache_free(skgl_context *ctx, skgl_shadow *s)
{
    int i;
    skgl__delete_texture(ctx, &s->cache.tex);
    skgl__delete_texture(ctx, &s->cache.verify_tex);
    for (i = 0; i < SKGL_MAX_CASCADES; i++) skgl__delete_framebuffer(ctx, &s->cache.fbo[i]);
    skgl__delete_framebuffer(ctx, &s->cache.verify_fbo);
}
#endif /* SKGL_NO_CACHE */

/* an invalidated box: NULL (everything) or finite with min <= max */
static sk_result skgl__arg_box(skgl_context *ctx, const char *fn, const sk_aabb *box)
{
    if (box && !(sk__v3_finite(box->min) && sk__v3_finite(box->max) && box->min.x <= box->max.x &&
                 box->min.y <= box->max.y && box->min.z <= box->max.z))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: box: finite, min <= max on each axis", fn);
    return SK_OK;
}

#ifndef SKGL_NO_CACHE
/* box into a list of SKGL_CACHE_REGIONS; a full list's last entry takes the union */
static void skgl__dirty_add(sk_aabb *dirty, int *n, const sk_aabb *box)
{
    sk_aabb *u = &dirty[SKGL_CACHE_REGIONS - 1];
    if (*n < SKGL_CACHE_REGIONS) { dirty[(*n)++] = *box; return; }
    u->min = sk__v3(skgl__minf(u->min.x, box->min.x), skgl__minf(u->min.y, box->min.y), skgl__minf(u->min.z, box->min.z));
    u->max = sk__v3(skgl__maxf(u->max.x, box->max.x), skgl__maxf(u->max.y, box->max.y), skgl__maxf(u->max.z, box->max.z));
}
#endif

SKGLDEF sk_result skgl_shadow_invalidate(skgl_context *ctx, skgl_shadow *s, const sk_aabb *box)
{
    const char *fn = "skgl_shadow_invalidate";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_shadow_invalidate", 0);
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    SKGL__TRY(skgl__arg_box(ctx, fn, box));
#ifndef SKGL_NO_CACHE   /* compiled out, no light has a cache: nothing to redraw */
    if (!s->desc.cache || s->cache.all) return SK_OK;
    if (!box) s->cache.all = 1;
    else skgl__dirty_add(s->cache.dirty, &s->cache.ndirty, box);
#endif
    return SK_OK;
}

#ifndef SKGL_NO_CACHE
/* one caster pass of layer i with matrix vp into framebuffer fb: the
   casters of `cls` (SKGL__DRAW_*), in rect (NULL: the whole layer),
   cleared first unless it draws over what is there */
static sk_result skgl__cache_pass(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *rs, int i,
                                  const sk_mat4 *vp, skgl__uint fb, const int *rect, int cls, int clear)
{
    skgl_draw_info info;
    memset(&info, 0, sizeof info);
    info.kind = SKGL_PASS_DIRECTIONAL;
    info.index = i;
    return skgl__cached_pass(ctx, st, rs, vp, s->origin, fb, rect, s->desc.resolution, cls, clear, &info,
                             &s->stats.passes, &s->stats.texels);
}
#endif

#if !defined(SKGL_NO_CACHE) || !defined(SKGL_NO_RMSM)
/* a w x h rectangle of depth from (x, y) of src to (x + dx, y + dy) of dst
   (a blit obeys the scissor test: off) */
static void skgl__blit_depth(skgl_context *ctx, skgl__st *st, skgl__uint src, skgl__uint dst, int x, int y, int w,
                             int h, int dx, int dy)
{
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    skgl__st_set1(ctx, st, SKGL__S_READ_FB, (skgl__int)src);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)dst);
    ctx->gl.BlitFramebuffer(x, y, x + w, y + h, x + dx, y + dy, x + dx + w, y + dy + h, SKGL__DEPTH_BUFFER_BIT,
                            SKGL__NEAREST);
}
#endif
#ifndef SKGL_NO_CACHE
static void skgl__cache_copy(skgl_context *ctx, skgl__st *st, skgl_shadow *s, skgl__uint src, skgl__uint dst, int x,
                             int y, int w, int h, int dx, int dy)
{
    skgl__blit_depth(ctx, st, src, dst, x, y, w, h, dx, dy);
    s->stats.cache_copied += (double)w * h;
}

/* layer i scrolled by (dx, dy) texels: the overlap copied from the cache
   into the map, the exposed strips drawn there, the result copied back */
static sk_result skgl__cache_scroll(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *rs, int i,
                                    int dx, int dy)
{
    int res = s->desc.resolution, strip[4];
    int sx = dx < 0 ? -dx : 0, sy = dy < 0 ? -dy : 0, ax = dx < 0 ? -dx : dx, ay = dy < 0 ? -dy : dy;
    sk_result r = SK_OK, rc;
    skgl__cache_copy(ctx, st, s, s->cache.fbo[i], s->fbo[i], sx, sy, res - ax, res - ay, dx, dy);
    if (ax > 0) {   /* the columns that came into the map, full height */
        strip[0] = dx > 0 ? 0 : res - ax; strip[1] = 0; strip[2] = ax; strip[3] = res;
        r = skgl__cache_pass(ctx, st, s, rs, i, &s->cache.vp[i], s->fbo[i], strip, SKGL__DRAW_STATIC, 1);
    }
    if (ay > 0) {   /* the rows, less those columns */
        strip[0] = dx > 0 ? ax : 0; strip[1] = dy > 0 ? 0 : res - ay; strip[2] = res - ax; strip[3] = ay;
        rc = skgl__cache_pass(ctx, st, s, rs, i, &s->cache.vp[i], s->fbo[i], strip, SKGL__DRAW_STATIC, 1);
        if (r == SK_OK) r = rc;
    }
    skgl__cache_copy(ctx, st, s, s->fbo[i], s->cache.fbo[i], 0, 0, res, res, 0, 0);
    return r;
}

/* the static part of cached layer i this frame: whole, scrolled or as it
   was, then the invalidated regions; *same: the map's layer still equals
   the cache's. A layer drawn whole takes this frame's matrix; a kept one
   keeps its own (moved by the whole texels scrolled), so the next frames
   compare with what the layer holds. */
static sk_result skgl__cache_update(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *rs, int i)
{
    skgl__cache *c = &s->cache;
    int res = s->desc.resolution, dx = 0, dy = 0, k, nr, rects[SKGL_CACHE_REGIONS][4];
    double now[16];
    sk_result r = SK_OK, rc;
    skgl__world_matrix(&s->render_vp[i], s->origin, now);
    c->sx[i] = c->sy[i] = 0;
    if (c->all || !c->valid[i] || !skgl__cache_shift(c->world[i], now, res, &dx, &dy) || dx <= -res ||
        dx >= res || dy <= -res || dy >= res) {
        memcpy(c->world[i], now, sizeof now);
        c->vp[i] = s->render_vp[i];
        c->valid[i] = 1;
        c->same[i] = 0;
        c->how[i] = 0;
        s->stats.cache_full++;
        return skgl__cache_pass(ctx, st, s, rs, i, &c->vp[i], c->fbo[i], NULL, SKGL__DRAW_STATIC, 1);
    }
    /* a scroll by (dx, dy) texels moves the map's x and y by 2 dx / res, 2 dy / res in clip space */
    c->world[i][12] += 2.0 * dx / res;
    c->world[i][13] += 2.0 * dy / res;
    c->vp[i] = memcmp(c->world[i], now, sizeof now) == 0 ? s->render_vp[i] : skgl__origin_matrix(c->world[i], s->origin);
    c->how[i] = dx != 0 || dy != 0 ? 1 : 2;
    c->sx[i] = dx;
    c->sy[i] = dy;
    if (dx != 0 || dy != 0) {
        r = skgl__cache_scroll(ctx, st, s, rs, i, dx, dy);
        c->same[i] = 1;
        c->dyn[i][2] = c->dyn[i][3] = 0;
        s->stats.cache_scrolled++;
    } else s->stats.cache_reused++;
    nr = skgl__dirty_rects(c->world[i], c->dirty, c->ndirty, res, rects);
    for (k = 0; k < nr; k++) {
        rc = skgl__cache_pass(ctx, st, s, rs, i, &c->vp[i], c->fbo[i], rects[k], SKGL__DRAW_STATIC, 1);
        if (r == SK_OK) r = rc;
        c->same[i] = 0;
        s->stats.cache_regions++;
    }
    return r;
}

/* The map's layer i from the cache, then the dynamic casters over it.
   c->same[i]: the map equals the cache but inside c->dyn[i] (where the
   last frame's dynamic casters were drawn): only that is copied back when
   the cache did not change. With skgl_dynamic.bounds the dynamic casters
   are drawn in their rectangle alone (none when it misses the layer). */
static sk_result skgl__cache_dynamic(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *rs, int i)
{
    skgl__cache *c = &s->cache;
    int res = s->desc.resolution, rect[4] = {0, 0, 0, 0}, *d = c->dyn[i];
    sk_result r;
    if (!c->same[i]) skgl__cache_copy(ctx, st, s, c->fbo[i], s->fbo[i], 0, 0, res, res, 0, 0);
    else if (d[2] > 0) skgl__cache_copy(ctx, st, s, c->fbo[i], s->fbo[i], d[0], d[1], d[2], d[3], 0, 0);
    c->same[i] = 1;
    d[2] = d[3] = 0;
    if (!ctx->dyn.draw) return SK_OK;
    rect[2] = rect[3] = res;
    if (skgl__has_dynamic_bounds(&ctx->dyn.bounds) && !skgl__cache_box_rect(c->world[i], &ctx->dyn.bounds, res, rect))
        return SK_OK;
    r = skgl__cache_pass(ctx, st, s, rs, i, &c->vp[i], s->fbo[i], rect, SKGL__DRAW_DYNAMIC, 0);
    memcpy(d, rect, sizeof rect);
    return r;
}

/* the boxes and the world matrix the cache has were given relative to the
   world: an invalidated box is world space, as the API takes it */
static sk_result skgl__render_cached(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *rs)
{
    skgl__cache *c = &s->cache;
    int i;
    sk_result r = SK_OK, rc;
    s->stats.cache_full = s->stats.cache_scrolled = s->stats.cache_reused = s->stats.cache_regions = 0;
    s->stats.cache_copied = 0.0;
    for (i = 0; i < s->maps; i++) {
        if (i >= c->layers) {   /* past the budget: drawn every frame */
            rc = skgl__cache_pass(ctx, st, s, rs, i, &s->render_vp[i], s->fbo[i], NULL, SKGL__DRAW_ALL, 1);
        } else {
            rc = skgl__cache_update(ctx, st, s, rs, i);
            if (rc == SK_OK) rc = skgl__cache_dynamic(ctx, st, s, rs, i);
        }
        if (rc != SK_OK) { r = rc; c->valid[i] = 0; }
    }
    /* layers this frame did not use (LSPSM's partitions vary) missed its
       invalidations */
    for (; i < c->layers; i++) c->valid[i] = 0;
    c->ndirty = 0;
    c->all = 0;
    return r;
}

/* .verify_cache: a cached map (a layer, a page, a face) against the same
   map drawn uncached, both read back (a stall). A texel differs when the
   window depths differ by more than SKGL__VERIFY_DEPTH, 1e-5 (0.5 mm of a
   50 m depth range): the rasterizer sets up its depth planes in window
   coordinates, so a scrolled overlap, drawn at another window position,
   holds depths a few ulps off where the plane is steep (up to 2.8e-6
   measured along 300-frame walks, test_gl_cache_property); a caster that
   moved differs by its move (0.12 for test_gl_cache's box). Coverage can
   differ too: a scroll's float rounding may move a vertex across one of
   the rasterizer's subpixel steps (1/256 texel), which flips the texel
   whose centre lay on the edge, one here and there, each alone; a caster
   that moved changes every texel its outline swept or its depth changed,
   side by side. So a differing texel none of whose 8 neighbours differs
   is rounding; the others (runs) are a change the cache was not told of,
   and more than 1e-5 of the map's texels in runs fail the render. */
#define SKGL__VERIFY_DEPTH 1e-5f
#define SKGL__VERIFY_RUNS 1e-5

typedef struct skgl__verify_count {
    int runs, alone;               /* differing texels with a differing neighbour / without */
    float worst;                   /* the largest depth difference */
} skgl__verify_count;

static int skgl__verify_differ(const float *a, const float *b, int w, int h, int x, int y)
{
    size_t k = (size_t)y * (size_t)w + (size_t)x;
    return x >= 0 && y >= 0 && x < w && y < h && SK_FABS(a[k] - b[k]) > SKGL__VERIFY_DEPTH;
}

/* w x h texels of the cached map a against the uncached b, into *v */
static void skgl__verify_compare(const float *a, const float *b, int w, int h, skgl__verify_count *v)
{
    int x, y, dx, dy;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t k = (size_t)y * (size_t)w + (size_t)x;
            int run = 0;
            if (!(SK_FABS(a[k] - b[k]) > SKGL__VERIFY_DEPTH)) continue;
            if (SK_FABS(a[k] - b[k]) > v->worst) v->worst = SK_FABS(a[k] - b[k]);
            for (dy = -1; dy <= 1 && !run; dy++)
                for (dx = -1; dx <= 1 && !run; dx++) run = (dx || dy) && skgl__verify_differ(a, b, w, h, x + dx, y + dy);
            if (run) v->runs++;
            else v->alone++;
        }
}
#endif /* SKGL_NO_CACHE */

#if !defined(SKGL_NO_CACHE) || !defined(SKGL_NO_RMSM)
/* the scratch depth map of .verify_cache, w x h (made on first use) */
static sk_result skgl__verify_texture(skgl_context *ctx, skgl__st *st, skgl__uint *tex, skgl__uint *fbo, int w, int h,
                                      const char *fn)
{
    skgl__api *gl = &ctx->gl;
    if (*tex) return SK_OK;
    gl->GenTextures(1, tex);
    ctx->objects++;
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D), (skgl__int)*tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D));
    gl->TexImage2D(SKGL__TEXTURE_2D, 0, SKGL__DEPTH_COMPONENT32F, w, h, 0, SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_MAG_FILTER, SKGL__NEAREST);
    *fbo = skgl__framebuffer(ctx, st, 0, 0, *tex, -1);
    if (!*fbo) return skgl__fail(ctx, SK_ERR_GL, "%s: verify framebuffer incomplete", fn);
    return SK_OK;
}
#endif
#ifndef SKGL_NO_CACHE
static sk_result skgl__verify_target(skgl_context *ctx, skgl__st *st, skgl_shadow *s, int size)
{
    return skgl__verify_texture(ctx, st, &s->cache.verify_tex, &s->cache.verify_fbo, size, size, "skgl_shadow_render");
}

/* the depth of rectangle (x, y, w, h) of framebuffer fb, read back into out */
static void skgl__verify_read(skgl_context *ctx, skgl__st *st, skgl__uint fb, int x, int y, int w, int h, float *out)
{
    skgl__st_pack(ctx, st, 0, w, 4 * w);
    skgl__st_set1(ctx, st, SKGL__S_READ_FB, (skgl__int)fb);
    ctx->gl.ReadPixels(x, y, w, h, SKGL__DEPTH_COMPONENT, SKGL__FLOAT, out);
}

/* Every cached layer against a render of all its casters with the
   matrix the layer holds (skgl__cache_update: this frame's when it was
   drawn whole, else its own, within 1e-3 texel of this frame's). The log
   says what the cache did with the failing layer and what it saw. */
static sk_result skgl__cache_verify(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *rs)
{
    skgl__cache *c = &s->cache;
    int i, res = s->desc.resolution, bad = -1, runs = 0;
    size_t n = (size_t)res * (size_t)res;
    skgl__verify_count v[SKGL_MAX_CASCADES];
    float *a, *b;
    sk_result r = skgl__verify_target(ctx, st, s, res);
    if (r != SK_OK) return r;
    a = (float *)SKGL_MALLOC(n * sizeof *a);
    b = (float *)SKGL_MALLOC(n * sizeof *b);
    if (!a || !b) { SKGL_FREE(a); SKGL_FREE(b); return SK_ERR_CAPACITY; }
    memset(v, 0, sizeof v);
    for (i = 0; i < s->maps && i < c->layers && r == SK_OK; i++) {
        r = skgl__cache_pass(ctx, st, s, rs, i, &c->vp[i], c->verify_fbo, NULL, SKGL__DRAW_ALL, 1);
        s->stats.passes -= skgl__pass_callbacks(ctx);   /* not the cache's work */
        s->stats.texels -= (double)res * res;
        skgl__verify_read(ctx, st, s->fbo[i], 0, 0, res, res, a);
        skgl__verify_read(ctx, st, c->verify_fbo, 0, 0, res, res, b);
        skgl__verify_compare(a, b, res, res, &v[i]);
        if (v[i].runs > runs) { runs = v[i].runs; bad = i; }
    }
    SKGL_FREE(a);
    SKGL_FREE(b);
    s->stats.cache_verify_texels = runs;
    if (r == SK_OK && runs > (int)(SKGL__VERIFY_RUNS * (double)n)) {
        char did[64];
        if (c->how[bad] == 1) snprintf(did, sizeof did, "scrolled by (%d, %d) texels", c->sx[bad], c->sy[bad]);
        else snprintf(did, sizeof did, "%s", c->how[bad] ? "reused as it was" : "drawn whole");
        r = skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_shadow_render: desc.verify_cache: layer %d (%s this frame) "
                       "differs from the uncached map in %d texels side by side, by up to %g in depth: a caster "
                       "scene.draw draws changed without skgl_shadow_invalidate (moving casters belong in "
                       "skgl_set_dynamic); %d texels alone, a scroll's float rounding, accepted",
                       bad, did, runs, (double)v[bad].worst, v[bad].alone);
    }
    return r;
}
#endif /* SKGL_NO_CACHE */

// >>rmsm_cache
#ifndef SKGL_NO_RMSM
/* RMSM's page cache (desc.cache). The virtual map's texel
   grid is fixed in light space (skgl__rmsm_frame), so a page keeps its
   depth from frame to frame: a pool slot holds it while it is requested
   and, after, until the slot is needed (least recently used first). Only
   pages that came into the view, or that an invalidated box or a new
   virtual frustum emptied, are drawn; the dynamic casters are drawn over
   the static depth of the pages they touch, restored from a static copy
   of the pool the next frame. */
#define SKGL__PAGE_LEVELS 11          /* levels of a virtual map of up to 1024 pages a side */

/* page (level, px, py) covers texels [px P - 1, (px+1) P + 1) of level l's
   virtual map (V / 2^l texels a side): its slot of P + 2 with a border of
   one texel each side. In NDC of the virtual map: */
static sk_rect skgl__page_rect(const skgl_shadow *s, const sk_page *pg)
{
    double lres = (double)(s->desc.resolution >> pg->level);
    int P = s->desc.rmsm_page_size;
    sk_rect r;
    r.x0 = (float)(2.0 * (pg->px * P - 1) / lres - 1.0);
    r.x1 = (float)(2.0 * ((pg->px + 1) * P + 1) / lres - 1.0);
    r.y0 = (float)(2.0 * (pg->py * P - 1) / lres - 1.0);
    r.y1 = (float)(2.0 * ((pg->py + 1) * P + 1) / lres - 1.0);
    return r;
}

#ifndef SKGL_NO_CACHE
/* the part (x, y, w, h in the pool) of page pg's slot at (sx, sy) that a
   texel rectangle of its level (skgl__cache_box_rect) covers; 0: none */
static int skgl__page_clip(const skgl_shadow *s, const sk_page *pg, const int *lrect, int sx, int sy, int out[4])
{
    int P = s->desc.rmsm_page_size, x0 = pg->px * P - 1, y0 = pg->py * P - 1;
    int a0 = lrect[0] > x0 ? lrect[0] : x0, b0 = lrect[1] > y0 ? lrect[1] : y0;
    int a1 = lrect[0] + lrect[2] < x0 + P + 2 ? lrect[0] + lrect[2] : x0 + P + 2;
    int b1 = lrect[1] + lrect[3] < y0 + P + 2 ? lrect[1] + lrect[3] : y0 + P + 2;
    if (a1 <= a0 || b1 <= b0) return 0;
    out[0] = sx + a0 - x0; out[1] = sy + b0 - y0; out[2] = a1 - a0; out[3] = b1 - b0;
    return 1;
}

/* each level's texel rectangle of a world box (0 in has[l]: it misses the level) */
static void skgl__page_box_rects(const skgl_shadow *s, const double *w, const sk_aabb *box, int rect[][4], int *has)
{
    int l;
    for (l = 0; l < s->rmsm.levels; l++) has[l] = skgl__cache_box_rect(w, box, s->desc.resolution >> l, rect[l]);
}
#endif

/* the slot's position in the pool */
static void skgl__slot_xy(const skgl_shadow *s, int k, int *x, int *y)
{
    *x = (k % s->desc.rmsm_pool_pages) * (s->desc.rmsm_page_size + 2);
    *y = (k / s->desc.rmsm_pool_pages) * (s->desc.rmsm_page_size + 2);
}

#ifndef SKGL_NO_CACHE
static int skgl__lru_order(const void *a, const void *b)
{
    unsigned x = ((const skgl__lru *)a)->last, y = ((const skgl__lru *)b)->last;
    return x < y ? -1 : x > y;
}

/* The page cache's bookkeeping before a render: a new virtual frustum or
   skgl_shadow_invalidate(NULL) empties every slot; an invalidated box
   empties the slots of the pages its shadow may touch (each level's texel
   rectangle of the box, skgl__cache_box_rect). Then each page of this
   frame keeps the slot it is resident in (pages_reused) or takes an empty
   slot, else the least recently used one (pages_evicted); a slot taken
   so is drawn (valid 0). There are always enough: a frame's pages fit in
   the pool (skgl__rmsm_pages), and the slots this frame keeps are its own. */
static void skgl__rmsm_assign(skgl_shadow *s)
{
    skgl__rmsm *m = &s->rmsm;
    skgl__cache *c = &s->cache;
    int cap = s->desc.rmsm_pool_pages * s->desc.rmsm_pool_pages, i, k, n = 0, used = 0;
    size_t bytes = (size_t)m->atlas_w * (size_t)m->atlas_h;
    skgl__lru *lru = m->lru;
    if (c->all || memcmp(&m->key_lvp, &m->lvp, sizeof m->lvp) != 0 ||
        memcmp(m->key_origin, m->origin, sizeof m->origin) != 0) {
        for (k = 0; k < cap; k++) m->slots[k].valid = m->slots[k].dyn = 0;
        memset(m->resident, 0, sizeof(int) * bytes);
        m->key_lvp = m->lvp;
        memcpy(m->key_origin, m->origin, sizeof m->origin);
        s->stats.cache_full = 1;
    } else if (c->ndirty > 0) {
        double w[16];
        int j, rect[SKGL__PAGE_LEVELS][4], has[SKGL__PAGE_LEVELS], clip[4];
        skgl__world_matrix(&m->lvp, m->origin, w);
        for (j = 0; j < c->ndirty; j++) {
            skgl__page_box_rects(s, w, &c->dirty[j], rect, has);
            for (k = 0; k < cap; k++) {
                skgl__rmsm_slot *t = &m->slots[k];
                sk_page pg;
                if (!t->valid || !has[t->level]) continue;
                pg.level = t->level; pg.px = t->px; pg.py = t->py;
                if (!skgl__page_clip(s, &pg, rect[t->level], 0, 0, clip)) continue;
                t->valid = t->dyn = 0;
                m->resident[skgl__atlas_index(s, t->level, t->px, t->py)] = 0;
                s->stats.cache_regions++;
            }
        }
    } else s->stats.cache_reused = 1;
    c->ndirty = 0;
    c->all = 0;
    m->frame++;
    for (i = 0; i < m->npages; i++) {
        k = m->resident[skgl__atlas_index(s, m->pages[i].level, m->pages[i].px, m->pages[i].py)] - 1;
        m->slot_of[i] = k;
        if (k >= 0) { m->slots[k].last = m->frame; s->stats.pages_reused++; used++; }
    }
    if (used == m->npages) return;
    for (k = 0; k < cap; k++)
        if (m->slots[k].last != m->frame) {
            lru[n].last = m->slots[k].valid ? m->slots[k].last + 1u : 0u;
            lru[n++].slot = k;
        }
    qsort(lru, (size_t)n, sizeof *lru, skgl__lru_order);
    for (i = 0, n = 0; i < m->npages; i++) {
        skgl__rmsm_slot *t;
        if (m->slot_of[i] >= 0) continue;
        t = &m->slots[k = lru[n++].slot];
        if (t->valid) {
            m->resident[skgl__atlas_index(s, t->level, t->px, t->py)] = 0;
            s->stats.pages_evicted++;
        }
        t->level = m->pages[i].level; t->px = m->pages[i].px; t->py = m->pages[i].py;
        t->valid = t->dyn = 0;
        t->last = m->frame;
        m->resident[skgl__atlas_index(s, t->level, t->px, t->py)] = k + 1;
        m->slot_of[i] = k;
    }
}
#endif /* SKGL_NO_CACHE */

/* the matrix that draws page i's slot (relative to rmsm.origin) */
static sk_mat4 skgl__page_vp(const skgl_shadow *s, int i)
{
    return sk_mat4_mul(sk_crop_matrix(skgl__page_rect(s, &s->rmsm.pages[i]), -1.0f, 1.0f), s->rmsm.lvp);
}

/* page i drawn in the page target (rmsm.page_fbo) at (0, 0): the casters
   of cls (SKGL__DRAW_*), the whole slot cleared first (rect NULL) or over
   what is there inside rect (slot texels) */
static sk_result skgl__page_draw(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *scene, int i,
                                 const int *rect, int cls)
{
    int slot = s->desc.rmsm_page_size + 2;
    sk_mat4 vp = skgl__page_vp(s, i);
    skgl_draw_info info;
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, slot, slot);
    memset(&info, 0, sizeof info);
    info.kind = SKGL_PASS_DIRECTIONAL;
    info.index = i;
    /* a whole page needs no scissor (the target is one slot), and leaving
       it off as the copy into the pool does saves two state changes per
       page; part of a page is drawn under its rectangle */
    return skgl__cached_pass(ctx, st, scene, &vp, s->rmsm.origin, s->rmsm.page_fbo, rect, slot, cls, rect == NULL,
                             &info, &s->stats.passes, &s->stats.texels);
}

/* One caster pass of page i into its slot of the pool framebuffer fb:
   the casters of cls (SKGL__DRAW_*), the whole slot cleared first (rect
   NULL) or over what is there inside rect (pool texels). The rasterizer's
   depth at a texel depends, in its last bits, on the texel's window
   position (its plane equations are set up in window coordinates), so a
   page drawn in place would hold other depths in another slot: every page
   is drawn at (0, 0) of the page target and copied into its slot, so a
   page's depth is the same in any slot, cached or not. */
static sk_result skgl__page_pass(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *scene, int i,
                                 skgl__uint fb, const int *rect, int cls)
{
    int x, y, slot = s->desc.rmsm_page_size + 2, local[4];
    sk_result r;
    skgl__slot_xy(s, s->rmsm.slot_of[i], &x, &y);
    if (rect) {   /* the slot's depth under rect first, to draw over */
        local[0] = rect[0] - x; local[1] = rect[1] - y; local[2] = rect[2]; local[3] = rect[3];
        skgl__blit_depth(ctx, st, fb, s->rmsm.page_fbo, rect[0], rect[1], rect[2], rect[3], -x, -y);
        r = skgl__page_draw(ctx, st, s, scene, i, local, cls);
        skgl__blit_depth(ctx, st, s->rmsm.page_fbo, fb, local[0], local[1], local[2], local[3], x, y);
        return r;
    }
    r = skgl__page_draw(ctx, st, s, scene, i, NULL, cls);
    skgl__blit_depth(ctx, st, s->rmsm.page_fbo, fb, 0, 0, slot, slot, x, y);
    return r;
}

/* desc.layered (uncached): pages first .. first + n - 1 (n up to
   SKGL_MAX_CASCADES) in one pass, page first + j into layer j of the batch
   target at (0, 0) (layered.geom: the page's matrix, gl_Layer j), then
   each layer copied into its page's slot of fb. The same matrix at the
   same window position as skgl__page_draw's: the depth of a pass per page
   but for the last bits where the geometry shader's matrix product rounds
   otherwise than the vertex shader's (llvmpipe: 0.16% of the texels, by
   up to 3 ulps). info->layer_index[j] is the page (first + j). */
static sk_result skgl__page_batch(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *scene,
                                  int first, int n, skgl__uint fb)
{
    int slot = s->desc.rmsm_page_size + 2, of[SKGL_MAX_CASCADES], page[SKGL_MAX_CASCADES], j, x, y;
    sk_mat4 vps[SKGL_MAX_CASCADES];
    skgl_draw_info info;
    sk_result r;
    for (j = 0; j < n; j++) {
        vps[j] = skgl__page_vp(s, first + j);
        of[j] = j;
        page[j] = first + j;
    }
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, slot, slot);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->rmsm.batch_fbo);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    skgl__clear_depth(ctx);   /* every layer */
    memset(&info, 0, sizeof info);
    info.kind = SKGL_PASS_DIRECTIONAL;
    r = skgl__casters_draw_layered_as(ctx, st, scene, vps, of, page, n, s->rmsm.origin, &info);
    s->stats.passes += skgl__pass_callbacks(ctx);
    s->stats.texels += (double)n * slot * slot;
    for (j = 0; j < n; j++) {
        skgl__slot_xy(s, s->rmsm.slot_of[first + j], &x, &y);
        skgl__blit_depth(ctx, st, s->rmsm.batch_layer_fbo[j], fb, 0, 0, slot, slot, x, y);
    }
    return r;
}

#ifndef SKGL_NO_CACHE
/* page i's slot from the map to the static copy (to 0) or back (to 1) */
static void skgl__page_copy(skgl_context *ctx, skgl__st *st, skgl_shadow *s, int i, int back)
{
    int x, y, slot = s->desc.rmsm_page_size + 2;
    skgl__slot_xy(s, s->rmsm.slot_of[i], &x, &y);
    skgl__cache_copy(ctx, st, s, back ? s->cache.fbo[0] : s->fbo[0], back ? s->fbo[0] : s->cache.fbo[0], x, y, slot,
                     slot, 0, 0);
}

/* the static copy of the pool (cache.tex), made when dynamic casters
   first come, within cache_budget_kb; the map holds only static depth
   then (every slot's dyn 0), copied whole. 0: no copy (over the budget),
   the pages the dynamic casters touch are drawn whole each frame. */
static int skgl__rmsm_copy_ready(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    double bytes = 4.0 * s->tex_size * s->tex_size;
    if (s->cache.tex) return 1;
    if (s->desc.cache_budget_kb > 0 && bytes > 1024.0 * s->desc.cache_budget_kb) return 0;
    ctx->gl.GenTextures(1, &s->cache.tex);
    ctx->objects++;
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY), (skgl__int)s->cache.tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    ctx->gl.TexImage3D(SKGL__TEXTURE_2D_ARRAY, 0, SKGL__DEPTH_COMPONENT32F, s->tex_size, s->tex_size, 1, 0,
                       SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    ctx->gl.TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST);
    ctx->gl.TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MAG_FILTER, SKGL__NEAREST);
    s->cache.fbo[0] = skgl__framebuffer(ctx, st, 0, 0, s->cache.tex, 0);
    if (!s->cache.fbo[0]) { skgl__delete_texture(ctx, &s->cache.tex); return 0; }
    skgl__cache_copy(ctx, st, s, s->fbo[0], s->cache.fbo[0], 0, 0, s->tex_size, s->tex_size, 0, 0);
    return 1;
}

/* The dynamic casters over the cached pages (skgl_set_dynamic): a page
   they touch (each level's texel rectangle of dyn.bounds; every page
   without bounds) gets its static depth back if they were drawn over it
   last time, then theirs, scissored to the rectangle; a page they left
   gets its static depth back. Without the static copy (budget) "back"
   means drawn again. */
static sk_result skgl__rmsm_dynamic(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *scene)
{
    skgl__rmsm *m = &s->rmsm;
    int i, bounds = skgl__has_dynamic_bounds(&ctx->dyn.bounds), slot = s->desc.rmsm_page_size + 2;
    int rect[SKGL__PAGE_LEVELS][4], has[SKGL__PAGE_LEVELS];
    sk_result r = SK_OK, rc;
    if (ctx->dyn.draw) (void)skgl__rmsm_copy_ready(ctx, st, s);
    if (ctx->dyn.draw && bounds) {
        double w[16];
        skgl__world_matrix(&m->lvp, m->origin, w);
        skgl__page_box_rects(s, w, &ctx->dyn.bounds, rect, has);
    }
    for (i = 0; i < m->npages; i++) {
        skgl__rmsm_slot *t = &m->slots[m->slot_of[i]];
        int x, y, clip[4], touch = ctx->dyn.draw != NULL;
        skgl__slot_xy(s, m->slot_of[i], &x, &y);
        clip[0] = x; clip[1] = y; clip[2] = clip[3] = slot;
        if (touch && bounds) touch = has[t->level] && skgl__page_clip(s, &m->pages[i], rect[t->level], x, y, clip);
        if (!touch && !t->dyn) continue;
        if (t->dyn) {
            if (s->cache.tex) skgl__page_copy(ctx, st, s, i, 1);
            else if ((rc = skgl__page_pass(ctx, st, s, scene, i, s->fbo[0], NULL, SKGL__DRAW_STATIC)) != SK_OK) r = rc;
            t->dyn = 0;
        }
        if (!touch) continue;
        rc = skgl__page_pass(ctx, st, s, scene, i, s->fbo[0], clip, SKGL__DRAW_DYNAMIC);
        if (rc != SK_OK) r = rc;
        t->dyn = 1;
    }
    return r;
}

/* .verify_cache for RMSM: every page of this frame drawn uncached (all
   its casters, in the page target as every page is drawn) against its
   slot; the tolerance of skgl__verify_compare, of the frame's page
   texels. A page's depth does not depend on its slot (skgl__page_pass):
   cached or not, none should differ. */
static sk_result skgl__rmsm_verify(skgl_context *ctx, skgl__st *st, skgl_shadow *s, const skgl_scene *scene)
{
    int i, slot = s->desc.rmsm_page_size + 2, bad = -1;
    size_t n = (size_t)slot * (size_t)slot;
    skgl__verify_count v, worst;
    float *a, *b;
    sk_result r = SK_OK;
    a = (float *)SKGL_MALLOC(n * sizeof *a);
    b = (float *)SKGL_MALLOC(n * sizeof *b);
    if (!a || !b) { SKGL_FREE(a); SKGL_FREE(b); return SK_ERR_CAPACITY; }
    memset(&v, 0, sizeof v);
    memset(&worst, 0, sizeof worst);
    for (i = 0; i < s->rmsm.npages && r == SK_OK; i++) {
        skgl__verify_count pv;
        int x, y;
        skgl__slot_xy(s, s->rmsm.slot_of[i], &x, &y);
        r = skgl__page_draw(ctx, st, s, scene, i, NULL, SKGL__DRAW_ALL);
        s->stats.passes -= skgl__pass_callbacks(ctx);   /* not the cache's work */
        s->stats.texels -= (double)n;
        skgl__verify_read(ctx, st, s->rmsm.page_fbo, 0, 0, slot, slot, b);
        skgl__verify_read(ctx, st, s->fbo[0], x, y, slot, slot, a);
        memset(&pv, 0, sizeof pv);
        skgl__verify_compare(a, b, slot, slot, &pv);
        v.runs += pv.runs;
        v.alone += pv.alone;
        if (pv.runs > worst.runs) { worst = pv; bad = i; }
    }
    SKGL_FREE(a);
    SKGL_FREE(b);
    s->stats.cache_verify_texels = v.runs;
    if (r == SK_OK && v.runs > (int)(SKGL__VERIFY_RUNS * (double)n * s->rmsm.npages)) {
        const sk_page *pg = &s->rmsm.pages[bad];
        r = skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_shadow_render: desc.verify_cache: the cached RMSM pages differ "
                       "from the uncached ones in %d texels side by side (page level %d (%d, %d) in %d, by up to %g "
                       "in depth): a caster scene.draw draws changed without skgl_shadow_invalidate (moving casters "
                       "belong in skgl_set_dynamic); %d texels alone, float rounding, accepted",
                       v.runs, pg->level, pg->px, pg->py, worst.runs, (double)worst.worst, v.alone);
    }
    return r;
}
#endif /* SKGL_NO_CACHE */

/* RMSM: this frame's pages into their pool slots (skgl__page_pass; with
   desc.layered SKGL_MAX_CASCADES at a pass, skgl__page_batch). With
   desc.cache (never layered: validated at create) only the slots
   skgl__rmsm_assign emptied are drawn, a pass each, with the static
   casters, then the dynamic ones over them (skgl__rmsm_dynamic). */
static sk_result skgl__render_rmsm(skgl_context *ctx, skgl_shadow *s, const skgl_scene *scene, sk_vec3 light_dir)
{
    skgl__st st;
    int i, cached = s->desc.cache, batched;
    sk_result r, rc;
    r = skgl__rmsm_frame(&s->rmsm.world, light_dir, &s->rmsm.lvp, s->rmsm.origin);
    if (r != SK_OK) return r;
    if (!s->rmsm.analyzed) {   /* no analysis: the coarsest page alone */
        s->rmsm.pages[0].level = s->rmsm.levels - 1;
        s->rmsm.pages[0].px = s->rmsm.pages[0].py = 0;
        s->rmsm.npages = 1;
        s->stats.pages_requested = 0;
        s->stats.rmsm_min_level = s->stats.rmsm_band = s->stats.rmsm_band_finer = 0;
    }
    s->stats.passes = 0;
    s->stats.texels = 0.0;
    s->stats.pages_rendered = s->stats.pages_reused = s->stats.pages_evicted = 0;
    s->stats.cache_full = s->stats.cache_scrolled = s->stats.cache_reused = s->stats.cache_regions = 0;
    s->stats.cache_copied = 0.0;
#ifndef SKGL_NO_CACHE
    if (cached) skgl__rmsm_assign(s);
    else
#endif
        for (i = 0; i < s->rmsm.npages; i++) s->rmsm.slot_of[i] = i;
    skgl__st_begin(ctx, &st);
    skgl__rmsm_table(ctx, &st, s);
    s->light_dir = sk__normalize(light_dir);
    s->vp[0] = skgl__shift(&s->rmsm.lvp, s->rmsm.origin, s->origin);
    s->maps = 1;
    skgl__timer_begin(ctx, &s->t_render);
    /* the pages are drawn relative to the virtual map's origin, not the
       camera's: the same depth whatever the camera, so a cached page equals
       the one an uncached render draws */
    batched = !cached && s->desc.layered && skgl__rmsm_batch_ready(ctx, &st, s);
    s->stats.layered = batched ? ctx->layered_state : 0;
    if (batched) skgl__casters_begin_layered(ctx, &st, s->desc.slope_bias, s->desc.depth_bias, s->rmsm.origin);
    else skgl__casters_begin(ctx, &st, s->desc.slope_bias, s->desc.depth_bias, s->rmsm.origin);
    for (i = 0; batched && i < s->rmsm.npages; i += SKGL_MAX_CASCADES) {
        int n = s->rmsm.npages - i < SKGL_MAX_CASCADES ? s->rmsm.npages - i : SKGL_MAX_CASCADES;
        rc = skgl__page_batch(ctx, &st, s, scene, i, n, s->fbo[0]);
        if (rc != SK_OK) r = rc;
        s->stats.pages_rendered += n;
    }
    for (i = 0; !batched && i < s->rmsm.npages; i++) {
        skgl__rmsm_slot *t = cached ? &s->rmsm.slots[s->rmsm.slot_of[i]] : NULL;
        if (t && t->valid) continue;
        rc = skgl__page_pass(ctx, &st, s, scene, i, s->fbo[0], NULL, cached ? SKGL__DRAW_STATIC : SKGL__DRAW_ALL);
        if (rc != SK_OK) r = rc;
        s->stats.pages_rendered++;
        if (!t) continue;
        t->valid = rc == SK_OK;
#ifndef SKGL_NO_CACHE
        if (s->cache.tex) skgl__page_copy(ctx, &st, s, i, 0);
#endif
    }
#ifndef SKGL_NO_CACHE
    if (cached) {
        rc = skgl__rmsm_dynamic(ctx, &st, s, scene);
        if (r == SK_OK) r = rc;
        if (r == SK_OK && s->desc.verify_cache) r = skgl__rmsm_verify(ctx, &st, s, scene);
    }
#endif
    skgl__model_end(ctx);
    skgl__timer_end(ctx, &s->t_render);
    s->stats.shadow_ms = s->t_render.ms;
    s->stats.maps = 1;
    s->stats.resolution = s->desc.resolution;
    s->stats.map_width = s->stats.map_height = s->tex_size;
    s->stats.pages_resident = s->rmsm.npages;
    if (cached) {
        int k, cap = s->desc.rmsm_pool_pages * s->desc.rmsm_pool_pages;
        for (k = 0, s->stats.pages_resident = 0; k < cap; k++) s->stats.pages_resident += s->rmsm.slots[k].valid;
        s->stats.cache_bytes = s->cache.tex ? 4.0 * s->tex_size * s->tex_size : 0.0;
    }
    skgl__st_end(ctx, &st);
    return r != SK_OK ? r : skgl__check(ctx, "skgl_shadow_render");
}
#endif /* SKGL_NO_RMSM */

/* ---- 6.6 analyze and render ------------------------------------------- */
// >>render
/* every layer's caster pass, into its own framebuffer (scene relative to
   the light's origin, as the fits saw it) */
static sk_result skgl__render_layers(skgl_context *ctx, skgl_shadow *s, const skgl_scene *rs, sk_vec3 light_dir)
{
    skgl__st st;
    sk_result r = SK_OK, rc;
    int i, res;
    const double *o = s->origin;
    /* a map smaller than its texture (FERKO, AUTO): the fit set both matrices */
    if (s->view_w == s->tex_size && s->view_h == s->tex_size)
        for (i = 0; i < s->maps; i++) s->render_vp[i] = s->vp[i];
    s->light_dir = sk__normalize(light_dir);
    res = s->tex_size;
    skgl__st_begin(ctx, &st);
    skgl__timer_begin(ctx, &s->t_render);
    skgl__st_set4(ctx, &st, SKGL__S_VIEWPORT, 0, 0, s->view_w, s->view_h);
    /* a map smaller than its texture (FERKO, AUTO): clear and draw only its
       region, plus one texel for the filter's footprint at the edge */
    if (s->view_w < res || s->view_h < res) {
        skgl__st_set1(ctx, &st, SKGL__S_SCISSOR_TEST, 1);
        skgl__st_set4(ctx, &st, SKGL__S_SCISSOR_BOX, 0, 0, s->view_w < res ? s->view_w + 1 : res,
                      s->view_h < res ? s->view_h + 1 : res);
    } else skgl__st_set1(ctx, &st, SKGL__S_SCISSOR_TEST, 0);
    s->stats.passes = 0;
    s->stats.texels = 0.0;
    s->stats.layered = 0;
    if (s->desc.layered && s->maps > 1 && skgl__layered_ready(ctx)) {
        /* every layer in one pass (LAYERED PASSES) */
        int of[SKGL_MAX_CASCADES];
        skgl_draw_info info;
        if (!s->fbo_layered) s->fbo_layered = skgl__framebuffer(ctx, &st, 0, 0, s->tex, SKGL__ALL_LAYERS);
        if (s->fbo_layered) {
            skgl__st_set1(ctx, &st, SKGL__S_DRAW_FB, (skgl__int)s->fbo_layered);
            skgl__clear_depth(ctx);   /* every layer */
            skgl__casters_begin_layered(ctx, &st, s->desc.slope_bias, s->desc.depth_bias, o);
            for (i = 0; i < s->maps; i++) of[i] = i;
            memset(&info, 0, sizeof info);
            info.kind = SKGL_PASS_DIRECTIONAL;
            r = skgl__casters_draw_layered(ctx, &st, rs, s->render_vp, of, s->maps, o, &info);
            s->stats.passes = skgl__pass_callbacks(ctx);
            s->stats.texels = (double)s->maps * s->view_w * s->view_h;
            s->stats.layered = ctx->layered_state;
        }
    }
    if (!s->stats.layered) skgl__casters_begin(ctx, &st, s->desc.slope_bias, s->desc.depth_bias, o);
#ifndef SKGL_NO_CACHE
    if (s->desc.cache) {   /* CACHED MAPS (never layered: validated at create) */
        r = skgl__render_cached(ctx, &st, s, rs);
        if (r == SK_OK && s->desc.verify_cache) r = skgl__cache_verify(ctx, &st, s, rs);
    }
#endif
    for (i = 0; !s->stats.layered && !s->desc.cache && i < s->maps; i++) {
        skgl_draw_info info;
        skgl__st_set1(ctx, &st, SKGL__S_DRAW_FB, (skgl__int)s->fbo[i]);
        skgl__clear_depth(ctx);
        memset(&info, 0, sizeof info);
        info.kind = SKGL_PASS_DIRECTIONAL;
        info.index = i;
        rc = skgl__casters_draw(ctx, &st, rs, &s->render_vp[i], o, &info);
        if (rc != SK_OK) r = rc;
        s->stats.passes += skgl__pass_callbacks(ctx);
        s->stats.texels += (double)s->view_w * s->view_h;
    }
    skgl__model_end(ctx);
    /* EVSM: the moments, timed with the depth passes */
    if (r == SK_OK && s->desc.filter == SKGL_FILTER_EVSM) skgl__evsm_moments(ctx, &st, s);
    skgl__timer_end(ctx, &s->t_render);
    s->stats.shadow_ms = s->t_render.ms;
    s->stats.maps = s->maps;
    s->stats.resolution = s->desc.resolution;
    s->stats.map_width = s->view_w;
    s->stats.map_height = s->view_h;
    skgl__st_end(ctx, &st);
    return r != SK_OK ? r : skgl__check(ctx, "skgl_shadow_render");
}
/* the techniques' table (its rows are declared with the light, in 6) */
#ifndef SKGL_NO_FERKO
/* .fit_to_depth: FERKO's analysis targets and ring, for the depth range */
static sk_result skgl__depth_fit_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    return s->desc.fit_to_depth ? skgl__ferko_create(ctx, st, s) : SK_OK;
}
#endif

/* whether skgl_shadow_analyze has anything to do for s */
static int skgl__analyzes(const skgl_shadow *s)
{
    return skgl__technique_of(s)->analyze && (s->desc.fit_to_depth || skgl__technique_of(s)->analyses);
}

/* a row's create, destroy, frame and analyze where .fit_to_depth may ask
   for the depth analysis (compiled out with it: SKGL_NO_FERKO) */
#ifndef SKGL_NO_FERKO
#define SKGL__DEPTH_FIT_ENTRIES skgl__depth_fit_create, skgl__ferko_destroy, NULL, skgl__analyze_ferko
#else
#define SKGL__DEPTH_FIT_ENTRIES NULL, NULL, NULL, NULL
#endif

static const skgl__technique skgl__techniques[] = {
    {"STANDARD", 0, 1, 0, 0, SKGL__DEPTH_FIT_ENTRIES, skgl__fit_ortho_layers, skgl__render_layers, NULL, NULL},
    {"PSSM", 0, 1, 0, 0, SKGL__DEPTH_FIT_ENTRIES, skgl__fit_ortho_layers, skgl__render_layers, NULL, NULL},
    {"PSM", 0, 1, 0, 0, NULL, NULL, NULL, NULL, skgl__fit_psm_layer, skgl__render_layers, NULL, NULL},
    {"LISPSM", 0, 1, 0, 0, SKGL__DEPTH_FIT_ENTRIES, skgl__fit_lispsm_layers, skgl__render_layers, NULL, NULL},
    {"LSPSM", 0, 1, 0, 1, NULL, NULL, NULL, NULL, skgl__fit_lspsm_layers, skgl__render_layers, NULL, NULL},
#ifndef SKGL_NO_FERKO
    {"FERKO", 1, 1, 0, 0, skgl__ferko_create, skgl__ferko_destroy, NULL, skgl__analyze_ferko, skgl__fit_ferko_layer,
     skgl__render_layers, NULL, NULL},
#else   /* refused at create (skgl__shadow_validate), as are AUTO and .fit_to_depth */
    {"FERKO", 0, 1, 0, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL},
#endif
#ifndef SKGL_NO_RMSM
    {"RMSM", 1, 2, 1, 0, skgl__rmsm_create, skgl__rmsm_free, skgl__rmsm_analysis_frame, skgl__analyze_rmsm,
     skgl__fit_rmsm, skgl__render_rmsm, skgl__rmsm_bind, skgl__rmsm_mask},
#else
    /* refused at create (skgl__shadow_validate) */
    {"RMSM", 0, 1, 0, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL},
#endif
#ifndef SKGL_NO_FERKO
    {"AUTO", 1, 1, 0, 0, skgl__ferko_create, skgl__ferko_destroy, NULL, skgl__analyze_auto, skgl__fit_auto,
     skgl__render_auto, NULL, NULL},
#else
    {"AUTO", 0, 1, 0, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL},
#endif
};

/* the row of s's technique (validated at create: always in the table) */
static const skgl__technique *skgl__technique_of(const skgl_shadow *s)
{
    return &skgl__techniques[s->desc.technique];
}

SKGLDEF sk_result skgl_shadow_analyze(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                      const skgl_scene *scene, sk_vec3 light_dir, unsigned depth_tex)
{
    skgl__st st;
    sk_mat4 inv, lvp;
    int w = 0, h = 0;
    double o[3];
    skgl_camera rc;
    skgl__cam ci;
    skgl_scene rs;
    sk_result r;
    const char *why;
    const char *fn = "skgl_shadow_analyze";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_shadow_analyze", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_shadow_analyze"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    if (!skgl__analyzes(s))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: s->desc.technique = %d: only SKGL_FERKO, SKGL_RMSM, "
                          "SKGL_AUTO and lights with desc.fit_to_depth analyse",
                          fn, (int)s->desc.technique);
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, scene ? &scene->bounds : NULL, &ci));
    SKGL__TRY(skgl__arg_scene(ctx, fn, scene, 0));
    SKGL__TRY(skgl__arg_vec(ctx, fn, light_dir, "light_dir", 1));
    SKGL__TRY(skgl__arg_name(ctx, fn, depth_tex, "depth_tex"));
    /* positions and the light frustum relative to the camera's origin; the
       depth buffer read in the caller's convention (cam->proj) */
    skgl__origin(&cam->view, o);
    rc = skgl__camera_rel(&ci.gl, o);
    rs = skgl__scene_rel(scene, o);
    if (!sk_mat4_inverse(sk_mat4_mul(cam->proj, rc.view), &inv)) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj * cam->view is singular near this camera's origin", fn);
    memcpy(ctx->cam_dmap, ci.dmap, sizeof ci.dmap);
    {
        /* view depth = -(row 2 of P^-1 . ndc) / (row 3 of P^-1 . ndc); the
           view matrix is rigid, so row 3 of (P V)^-1 is P^-1's */
        sk_mat4 pinv;
        int k;
        if (!sk_mat4_inverse(cam->proj, &pinv)) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj is singular", fn);
        for (k = 0; k < 4; k++) ctx->cam_view_z[k] = pinv.m[k * 4 + 2];
    }
    if (skgl__technique_of(s)->frame) r = skgl__technique_of(s)->frame(scene, &rs, light_dir, o, &lvp);
    else r = skgl__ferko_light(&rs, light_dir, &lvp);
    if (r != SK_OK) return r;
    skgl__st_begin(ctx, &st);
    why = skgl__texture_size(ctx, &st, depth_tex, &w, &h);
    if (why) {
        skgl__st_end(ctx, &st);
        skgl__set_log(ctx, "skgl_shadow_analyze: depth_tex", why);
        return SK_ERR_INVALID_ARG;
    }
    r = skgl__technique_of(s)->analyze(ctx, &st, s, cam, &inv, &lvp, o, depth_tex, w, h);
    skgl__st_end(ctx, &st);
    return r != SK_OK ? r : skgl__check(ctx, "skgl_shadow_analyze");
}

SKGLDEF sk_result skgl_shadow_render(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                     const skgl_scene *scene, sk_vec3 light_dir)
{
    sk_result r;
    double o[3], was[3];
    skgl_camera rcam;
    skgl__cam ci;
    skgl_scene rs;
    const char *fn = "skgl_shadow_render";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_shadow_render", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_shadow_render"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, scene ? &scene->bounds : NULL, &ci));
    SKGL__TRY(skgl__arg_scene(ctx, fn, scene, 1));
    SKGL__TRY(skgl__arg_vec(ctx, fn, light_dir, "light_dir", 1));
    /* the maps are fitted and rendered relative to the camera's origin */
    skgl__origin(&cam->view, o);
    rcam = skgl__camera_rel(&ci.gl, o);
    rs = skgl__scene_rel(scene, o);
    memcpy(was, s->origin, sizeof was);
    memcpy(s->origin, o, sizeof o);
    s->rmsm.world = scene->bounds;
    r = skgl__fit_layers(s, &rcam, &rs, light_dir);
    if (r != SK_OK) {
        memcpy(s->origin, was, sizeof was);
        return skgl__said(ctx, fn, r, "the maps cannot be fitted to this camera and scene: cam->proj must be a "
                          "perspective or orthographic projection with 0 < near < far and an invertible cam->view, "
                          "and scene->bounds a box of finite extent");
    }
    skgl__clip_depth(ctx, 0);
    r = skgl__technique_of(s)->render(ctx, s, &rs, light_dir);
    skgl__clip_depth(ctx, 1);
    if (r == SK_OK) s->rendered = 1;
    return skgl__said(ctx, fn, r, NULL);
}

/* ---- 6.6, the filterable map: EVSM moments ---------------------------- */
// >>evsm
/* Exponential variance shadow maps (Lauritzen and McCool 2008, Sec. 4):
   depth x = 2 z - 1 in [-1, 1] warped by exp(c+ x) and -exp(-c- x); with
   c+ = c- = 40 the squares stay below 32-bit float's largest (e^80 ~ 5.5e34;
   Lauritzen's bound is 42) and a blur of 129 of them too. */
#define SKGL__EVSM_POS 40.0f
#define SKGL__EVSM_NEG 40.0f
/* the smallest variance, as a spread of window depth: above the rounding of
   E[w^2] - E[w]^2 in 32-bit floats (a relative 1.2e-7 of w^2, a spread of
   about 4e-6 at c = 40) */
#define SKGL__EVSM_SPREAD 1e-4f
/* the fewest moments texels across the blur's box: a box wider than this
   many map texels is evaluated on a coarser grid (skgl__evsm_side), so the
   passes read at most about 2 (SPAN + 1) map texels per map texel at any
   width; the receiver's bilinear tap between grid points errs by at most
   1/(4 SPAN) of a step's moments (at the box's corners). 5: the default
   blur (2) keeps the map's own grid. */
#define SKGL__EVSM_SPAN 5

/* the blur's two programs and the EVSM mask, made with the first EVSM light
   and kept with the context; the blur reads the depth (horizontal) or the
   moments (vertical) on unit 0 */
static sk_result skgl__evsm_programs(skgl_context *ctx, skgl__st *st)
{
    skgl__api *gl = &ctx->gl;
    int k;
    if (!ctx->mask_evsm.prog) {
        skgl__uint p = skgl__mask_program(ctx, 1);
        if (!p) return SK_ERR_GL;
        skgl__mask_swap(ctx);
        ctx->mask_prog = p;
        skgl__mask_locations(ctx, st);
        skgl__mask_swap(ctx);
    }
    for (k = 0; k < 2; k++) {
        skgl__uint p = ctx->evsm_prog[k];
        float c[2];
        if (p) continue;
        p = skgl__program(ctx, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT), k ? "#define SK_EVSM_VERTICAL 1\n" : "",
                          skgl__glsl(SKGL__GLSL_EVSM_MOMENTS_FRAG));
        if (!p) return SK_ERR_GL;
        ctx->evsm_prog[k] = p;
        ctx->evsm_u_box[k] = gl->GetUniformLocation(p, "u_box");
        ctx->evsm_u_extent[k] = gl->GetUniformLocation(p, "u_extent");
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
        skgl__u1i(gl, gl->GetUniformLocation(p, k ? "u_src" : "u_depth"), 0);
        if (k) continue;
        ctx->evsm_u_layer = gl->GetUniformLocation(p, "u_layer");
        c[0] = SKGL__EVSM_POS;
        c[1] = SKGL__EVSM_NEG;
        gl->Uniform2fv(gl->GetUniformLocation(p, "u_exponents"), 1, c);
    }
    return SK_OK;
}

/* a framebuffer drawing into one layer of a colour array texture, checked
   complete (0: not) */
static skgl__uint skgl__layer_framebuffer(skgl_context *ctx, skgl__st *st, skgl__uint tex, int layer)
{
    skgl__api *gl = &ctx->gl;
    skgl__uint fb = 0;
    gl->GenFramebuffers(1, &fb);
    ctx->objects++;
    skgl__st_framebuffer(ctx, st, fb);
    gl->FramebufferTextureLayer(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT0, tex, 0, layer);
    if (gl->CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) == SKGL__FRAMEBUFFER_COMPLETE) return fb;
    skgl__delete_framebuffer(ctx, &fb);
    /* the tracked binding named the framebuffer just deleted: GL fell back to 0 */
    st->cur[SKGL__S_DRAW_FB][0] = 0;
    st->cur[SKGL__S_READ_FB][0] = 0;
    return 0;
}

/* the moments' side for a map of n texels a side and a blur of r: n while
   the box (2r + 1 texels) spans at most SKGL__EVSM_SPAN of them, else the
   fewest texels that put SKGL__EVSM_SPAN grid points across the box */
static int skgl__evsm_side(int n, int r)
{
    long w = 2L * r + 1;
    if (w <= SKGL__EVSM_SPAN) return n;
    return (int)(((long)n * SKGL__EVSM_SPAN + w - 1) / w);
}

/* the moments texels a pass writes along an axis where the frame rendered
   `rendered` of the map's n texels (m: the moments' side): those a
   bilinear tap inside the rendered region reaches, one past its edge */
static int skgl__evsm_reach(int rendered, int n, int m)
{
    long k = ((long)rendered * m + n - 1) / n + 1;
    return k < m ? (int)k : m;
}

/* the light's moments array (one layer per map, size x size) and the
   horizontal pass's target (size x the map's side); 16 bytes a texel */
static sk_result skgl__evsm_create(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    skgl__api *gl = &ctx->gl;
    int i, n = s->tex_size, m = skgl__evsm_side(n, s->desc.evsm_blur);
    s->evsm.size = m;
    SKGL__TRY(skgl__evsm_programs(ctx, st));
    gl->GenTextures(1, &s->evsm.tex);
    ctx->objects++;
    skgl__st_unpack(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY), (skgl__int)s->evsm.tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    gl->TexImage3D(SKGL__TEXTURE_2D_ARRAY, 0, SKGL__RGBA32F, m, m, s->layers, 0, SKGL__RGBA, SKGL__FLOAT, NULL);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MIN_FILTER, SKGL__LINEAR);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_MAG_FILTER, SKGL__LINEAR);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_WRAP_S, SKGL__CLAMP_TO_EDGE);
    gl->TexParameteri(SKGL__TEXTURE_2D_ARRAY, SKGL__TEXTURE_WRAP_T, SKGL__CLAMP_TO_EDGE);
    for (i = 0; i < s->layers; i++)
        if (!(s->evsm.fbo[i] = skgl__layer_framebuffer(ctx, st, s->evsm.tex, i))) return SK_ERR_GL;
    s->evsm.tmp = skgl__color_texture(ctx, st, SKGL__RGBA32F, m, n, 1, SKGL__RGBA, SKGL__FLOAT, NULL);
    s->evsm.tmp_fbo = skgl__framebuffer(ctx, st, s->evsm.tmp, 1, 0, 0);
    return s->evsm.tmp_fbo ? SK_OK : SK_ERR_GL;
}

static void skgl__evsm_free(skgl_context *ctx, skgl_shadow *s)
{
    int i;
    skgl__delete_texture(ctx, &s->evsm.tex);
    skgl__delete_texture(ctx, &s->evsm.tmp);
    for (i = 0; i < SKGL_MAX_CASCADES; i++) skgl__delete_framebuffer(ctx, &s->evsm.fbo[i]);
    skgl__delete_framebuffer(ctx, &s->evsm.tmp_fbo);
}

/* After the depth passes: each map's moments, box-filtered over
   2 evsm_blur + 1 map texels a side in two passes (evsm_moments.frag),
   evaluated on the moments' grid (evsm.size a side: the map's own, or a
   coarser one for a wide box, skgl__evsm_side); two draws and the same
   calls per map at every radius, and about the same texels read. Only the
   region this frame rendered (FERKO, AUTO: view_w x view_h) is read, and
   the moments it reaches written. Under the render's tracker st, after
   its caster passes. */
static void skgl__evsm_moments(skgl_context *ctx, skgl__st *st, skgl_shadow *s)
{
    skgl__api *gl = &ctx->gl;
    int n = s->tex_size, m = s->evsm.size, i, k;
    int mw = skgl__evsm_reach(s->view_w, n, m), mh = skgl__evsm_reach(s->view_h, n, m);
    float box[2], ext[2][2];
    box[0] = (float)s->desc.evsm_blur + 0.5f;
    box[1] = (float)n / (float)m;
    /* the horizontal pass reads the depth's region, the vertical its own output */
    ext[0][0] = (float)s->view_w;
    ext[0][1] = ext[1][1] = (float)s->view_h;
    ext[1][0] = (float)mw;
    skgl__st_screen_pass(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    for (i = 0; i < s->maps; i++)
        for (k = 0; k < 2; k++) {
            skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)(k ? s->evsm.fbo[i] : s->evsm.tmp_fbo));
            skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, mw, k ? mh : s->view_h);
            skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->evsm_prog[k]);
            if (k) skgl__st_texture(ctx, st, 0, SKGL__T_2D, s->evsm.tmp, ctx->point_sampler);
            else skgl__st_texture(ctx, st, 0, SKGL__T_2D_ARRAY, s->tex, ctx->point_sampler);
            gl->Uniform2fv(ctx->evsm_u_box[k], 1, box);
            if (ctx->evsm_u_extent[k] >= 0) gl->Uniform2fv(ctx->evsm_u_extent[k], 1, ext[k]);
            if (!k) skgl__u1i(gl, ctx->evsm_u_layer, i);
            gl->DrawArrays(SKGL__TRIANGLES, 0, 3);
        }
}

/* ---- 6.7 bind: the snippet's uniforms in a forward shader ------------- */
// >>bind
/* The directional snippet's uniforms on the current program (entry e):
   the light's constants when the program holds another light's (or none),
   the values that seldom change when they did, the per-frame ones always.
   unit, table_unit: the units of the map and of the RMSM page table;
   origin: the world point the program's positions are relative to. */
static void skgl__shadow_uniforms(skgl_context *ctx, const skgl_shadow *s, skgl__progent *e, int unit,
                                  int table_unit, const double origin[3])
{
    const skgl__api *gl = &ctx->gl;
    const skgl__int *L = e->loc;
    sk_mat4 vp[SKGL_MAX_CASCADES];
    float ext[2];
    int i;
    if (e->owner != s->id || e->unit != unit) {
        /* the page table's sampler is set whatever the technique: two
           samplers of different types must never share a unit */
        skgl__u1i(gl, L[SKGL__L_MAP], unit);
        skgl__u1i(gl, L[SKGL__L_TABLE], table_unit);
        skgl__u1i(gl, L[SKGL__L_RMSM], skgl__technique_of(s)->pages);
        skgl__u1i(gl, L[SKGL__L_PAGES0], s->rmsm.pages0);
        skgl__u1i(gl, L[SKGL__L_LEVELS], s->rmsm.levels);
        skgl__u1i(gl, L[SKGL__L_PAGE], s->desc.rmsm_page_size);
        skgl__u1i(gl, L[SKGL__L_SELECT_BY_MAP], skgl__technique_of(s)->select_by_map);
        skgl__u1f(gl, L[SKGL__L_BLEND_BAND], s->desc.blend_band);
        skgl__u1f(gl, L[SKGL__L_NORMAL_BIAS], s->desc.normal_bias > 0.0f ? s->desc.normal_bias : 0.0f);
        skgl__u1i(gl, L[SKGL__L_BIAS_MODE], s->desc.bias == SKGL_BIAS_RECEIVER_PLANE ? 0 : 1);
        skgl__u1f(gl, L[SKGL__L_PLANE_BIAS], s->desc.plane_bias > 0.0f ? s->desc.plane_bias : 0.0f);
        skgl__u1i(gl, L[SKGL__L_PCF], s->desc.pcf_radius);
        skgl__u1f(gl, L[SKGL__L_FILTER_WORLD], s->desc.filter_world);
        if (L[SKGL__L_MOMENTS] >= 0) {   /* a program with SK_SHADOW_EVSM (the mask's always) */
            float k[4];
            k[0] = SKGL__EVSM_POS;
            k[1] = SKGL__EVSM_NEG;
            k[2] = s->desc.evsm_bleed;
            k[3] = SKGL__EVSM_SPREAD;
            skgl__u1i(gl, L[SKGL__L_MOMENTS], table_unit + 1);
            skgl__u1i(gl, L[SKGL__L_FILTER], s->desc.filter == SKGL_FILTER_EVSM);
            if (L[SKGL__L_EVSM] >= 0) gl->Uniform4fv(L[SKGL__L_EVSM], 1, k);
        }
        e->owner = s->id;
        e->unit = unit;
        e->sentinel_i = s->desc.rmsm_page_size;
        e->layers = e->min_level = -1;
        e->extent[0] = e->extent[1] = e->select = -1.0f;
    }
    if (e->layers != s->maps) { e->layers = s->maps; skgl__u1i(gl, L[SKGL__L_LAYERS], s->maps); }
    /* sk_rmsm_min_level: the finest level rendered, or -b when the pages
       are those of request band b: the lookup starts b levels under the
       pixel's, at or under every level band b asks for (a floor under
       the band, stats.rmsm_min_level > 0, holds no pages to find) */
    {
        int first = s->stats.rmsm_band > 0 ? -s->stats.rmsm_band : s->stats.rmsm_min_level;
        if (e->min_level != first) {
            e->min_level = first;
            skgl__u1i(gl, L[SKGL__L_MIN_LEVEL], e->min_level);
        }
    }
    /* FERKO and AUTO draw into the lower-left view_w x view_h texels:
       beyond them lie older maps' texels, not this frame's */
    ext[0] = skgl__technique_of(s)->pages ? 1.0f : (float)s->view_w / (float)s->tex_size;
    ext[1] = skgl__technique_of(s)->pages ? 1.0f : (float)s->view_h / (float)s->tex_size;
    if (ext[0] != e->extent[0] || ext[1] != e->extent[1]) {
        e->extent[0] = ext[0];
        e->extent[1] = ext[1];
        if (L[SKGL__L_MAP_EXTENT] >= 0) gl->Uniform2fv(L[SKGL__L_MAP_EXTENT], 1, ext);
    }
    if (e->select != s->select_extent) {
        e->select = s->select_extent;
        skgl__u1f(gl, L[SKGL__L_SELECT_EXTENT], s->select_extent);
    }
    /* per frame: the matrices, the split depths, the light's direction */
    for (i = 0; i < s->maps && i < SKGL_MAX_CASCADES; i++) vp[i] = skgl__shift(&s->vp[i], s->origin, origin);
    if (L[SKGL__L_LIGHT_VP] >= 0) gl->UniformMatrix4fv(L[SKGL__L_LIGHT_VP], s->maps, 0, vp[0].m);
    if (L[SKGL__L_SPLITS] >= 0) {
        float sp[SKGL_MAX_CASCADES + 2];
        memcpy(sp, s->stats.splits, sizeof(float) * (size_t)(s->maps + 1));
        sp[s->maps + 1] = s->fade_start < SK__INF ? s->fade_start : 3e38f;
        gl->Uniform1fv(L[SKGL__L_SPLITS], s->maps + 2, sp);
    }
    if (L[SKGL__L_LIGHT_DIR] >= 0) gl->Uniform3fv(L[SKGL__L_LIGHT_DIR], 1, &s->light_dir.x);
}

/* an EVSM light needs the snippet's EVSM part (SK_SHADOW_EVSM), and a
   program that has it takes three units from `unit` (sk_moments on
   unit + 2, of a sampler type of its own), whichever light it binds */
static sk_result skgl__evsm_program_fits(skgl_context *ctx, const char *fn, const skgl_shadow *s,
                                         const skgl__progent *e, skgl__uint program, int unit, const char *prefix)
{
    const char *p = prefix && prefix[0] ? prefix : "sk_";
    char up[SKGL_PREFIX_MAX + 1];
    int i;
    for (i = 0; p[i] && i < SKGL_PREFIX_MAX; i++) up[i] = (char)toupper((unsigned char)p[i]);
    up[i] = 0;
    if (s->desc.filter == SKGL_FILTER_EVSM && e->loc[SKGL__L_MOMENTS] < 0)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "%s: s->desc.filter = SKGL_FILTER_EVSM, but program = %u has no active uniform %smoments: "
                          "put \"#define %sSHADOW_EVSM 1\" before the snippet", fn, program, p, up);
    if (e->loc[SKGL__L_MOMENTS] >= 0 && unit > 29)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: unit = %d: a program with %sSHADOW_EVSM takes units unit .. "
                          "unit + 2: at most 29", fn, unit, up);
    return SK_OK;
}

SKGLDEF sk_result skgl_shadow_bind(skgl_context *ctx, const skgl_shadow *s, unsigned program, int unit)
{
    return skgl_shadow_bind_origin(ctx, s, program, unit, NULL);
}

SKGLDEF sk_result skgl_shadow_contact_depth(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                            unsigned depth_tex)
{
    const char *fn = "skgl_shadow_contact_depth";
    skgl__cam ci;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, fn, 0);
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, NULL, &ci));
    if (depth_tex && !ctx->gl.IsTexture(depth_tex))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: depth_tex = %u is not a texture", fn, depth_tex);
    s->contact_tex = depth_tex;
    s->contact_cam = *cam;
    memcpy(s->contact_dmap, ci.dmap, sizeof s->contact_dmap);
    return SK_OK;
}

/* The forward contact march (SK_SHADOW_CONTACT) on the current program,
   whose locations are looked up at its first bind (a program without the
   march: nothing after that). Its depth sampler is set to `unit` once (two
   samplers of different types must never share a unit, and GL's default
   is 0); a light with contact shadows and a depth buffer binds it there
   (a nearest, non-comparing sampler: texelFetch reads raw depth) and sets
   the march, the camera's matrices relative to origin as the shader's
   positions are; a light without turns a march the program holds off.
   Returns the unit it left active (-1: none). */
static skgl__int skgl__forward_contact(skgl_context *ctx, const skgl_shadow *s, skgl__progent *e, skgl__uint program,
                                       int unit, const double origin[3])
{
    static const char *const names[4] = {"sk_contact_depth", "sk_contact", "sk_contact_camera", "sk_contact_depth_map"};
    const skgl__api *gl = &ctx->gl;
    skgl_camera rc;
    sk_mat4 m[3];
    float c[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int i;
    if (!e->contact_looked) {
        char name[SKGL_PREFIX_MAX + 32];
        for (i = 0; i < 4; i++) {
            if (e->prefix[0]) snprintf(name, sizeof name, "%s%s", e->prefix, names[i] + 3);
            e->contact_loc[i] = gl->GetUniformLocation(program, e->prefix[0] ? name : names[i]);
        }
        e->contact_looked = 1;
        e->contact_unit = -1;
    }
    if (e->contact_loc[0] < 0) return -1;
    if (e->contact_unit != unit) {
        gl->Uniform1i(e->contact_loc[0], unit);
        e->contact_unit = unit;
    }
    rc = skgl__camera_rel(&s->contact_cam, origin);
    m[0] = sk_mat4_mul(rc.proj, rc.view);
    if (!(s->desc.contact_length > 0.0f && s->contact_tex) || !sk_mat4_inverse(m[0], &m[1])) {
        if (e->contact_on && e->contact_loc[1] >= 0) gl->Uniform4fv(e->contact_loc[1], 1, c);
        e->contact_on = 0;
        return -1;
    }
    m[2] = rc.view;
    c[0] = s->desc.contact_length;
    c[1] = (float)s->desc.contact_steps;
    c[2] = s->desc.contact_thickness;
    gl->ActiveTexture((skgl__enum)(SKGL__TEXTURE0 + unit));
    gl->BindTexture(SKGL__TEXTURE_2D, s->contact_tex);
    gl->BindSampler((skgl__uint)unit, ctx->point_sampler);
    if (e->contact_loc[1] >= 0) gl->Uniform4fv(e->contact_loc[1], 1, c);
    if (e->contact_loc[2] >= 0) gl->UniformMatrix4fv(e->contact_loc[2], 3, 0, m[0].m);
    if (e->contact_loc[3] >= 0) gl->Uniform4fv(e->contact_loc[3], 1, s->contact_dmap);
    e->contact_on = 1;
    return SKGL__TEXTURE0 + unit;
}

/* the active unit the caller had (default mode; -1 in caller-owns mode,
   where the bind leaves the last unit it used active) */
static skgl__int skgl__bind_active(skgl_context *ctx)
{
    skgl__int active = -1;
    if (!ctx->caller_owns) ctx->gl.GetIntegerv(SKGL__ACTIVE_TEXTURE, &active);
    return active;
}

SKGLDEF sk_result skgl_shadow_bind_origin(skgl_context *ctx, const skgl_shadow *s, unsigned program, int unit,
                                          const double origin[3])
{
    return skgl_shadow_bind_named(ctx, s, program, unit, NULL, origin);
}

SKGLDEF sk_result skgl_shadow_bind_named(skgl_context *ctx, const skgl_shadow *s, unsigned program, int unit,
                                         const char *prefix, const double origin[3])
{
    skgl__api *gl;
    skgl__int active, last;
    skgl__progent *e;
    const char *fn = "skgl_shadow_bind";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_shadow_bind_named", 0);
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    SKGL__TRY(skgl__arg_prefix(ctx, fn, prefix));
    SKGL__TRY(skgl__arg_name(ctx, fn, program, "program"));
    SKGL__TRY(skgl__arg_unit(ctx, fn, unit, 32 - skgl__technique_of(s)->units));
    if (origin && !(SK_FABS(origin[0]) < 1e30 && SK_FABS(origin[1]) < 1e30 && SK_FABS(origin[2]) < 1e30))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: origin = (%g %g %g): finite, under 1e30", fn, origin[0],
                          origin[1], origin[2]);
    if (!s->rendered)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: s: the light has not been rendered yet (skgl_shadow_render "
                          "first)", fn);
    SKGL__TRY(skgl__arg_program(ctx, fn, program));
    e = skgl__user_program(ctx, program, SKGL__PK_SHADOW, prefix ? prefix : "");
    SKGL__TRY(skgl__snippet_present(ctx, fn, e, SKGL__L_MAP, program, prefix, "sk_shadow_map"));
    SKGL__TRY(skgl__evsm_program_fits(ctx, fn, s, e, program, unit, prefix));
    gl = &ctx->gl;
    active = skgl__bind_active(ctx);
    last = SKGL__TEXTURE0 + unit;
    if (active != last) gl->ActiveTexture((skgl__enum)last);
    gl->BindTexture(SKGL__TEXTURE_2D_ARRAY, s->tex);
    gl->BindSampler((skgl__uint)unit, ctx->cmp_sampler);
    if (skgl__technique_of(s)->bind) last = skgl__technique_of(s)->bind(ctx, s, unit);
    /* the forward contact march (SK_SHADOW_CONTACT) on unit + 3 (unit + 2 is
       EVSM's): in a
       steady frame only a light with contact shadows costs a call */
    if (unit + 3 > 31 && s->desc.contact_length > 0.0f && s->contact_tex)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: unit = %d: contact shadows take unit + 3, at most 28", fn,
                          unit);
    if (unit + 3 <= 31) {
        skgl__int cu = skgl__forward_contact(ctx, s, e, program, unit + 3, origin ? origin : skgl__zero3);
        if (cu >= 0) last = cu;
    }
    if (s->desc.filter == SKGL_FILTER_EVSM) {   /* the moments, bilinear through the texture's own filter */
        last = SKGL__TEXTURE0 + unit + 2;
        gl->ActiveTexture((skgl__enum)last);
        gl->BindTexture(SKGL__TEXTURE_2D_ARRAY, s->evsm.tex);
        gl->BindSampler((skgl__uint)unit + 2, 0);
    }
    if (active >= 0 && active != last) gl->ActiveTexture((skgl__enum)active);
    skgl__shadow_uniforms(ctx, s, e, unit, unit + 1, origin ? origin : skgl__zero3);
    return skgl__check(ctx, "skgl_shadow_bind");
}

SKGLDEF sk_result skgl_unbind(skgl_context *ctx, int unit)
{
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_unbind", 0);
    SKGL__TRY(skgl__arg_unit(ctx, "skgl_unbind", unit, 30));
    ctx->gl.BindSampler((skgl__uint)unit, 0);
    ctx->gl.BindSampler((skgl__uint)unit + 1, 0);
    return skgl__check(ctx, "skgl_unbind");
}

/* ---- 6.8 the deferred mask ------------------------------------------- */
// >>mask
/* the contact march's uniforms (mask program current): length, steps,
   thickness, and the camera-relative view-projection the samples project by */
static void skgl__mask_contact(skgl_context *ctx, const skgl_shadow_desc *d, const skgl_camera *rc)
{
    float c[4];
    c[0] = d->contact_length;
    c[1] = (float)d->contact_steps;
    c[2] = d->contact_thickness;
    c[3] = 0.0f;
    /* the program keeps the last values: sent only when they change (a
       light without contact shadows costs no call after the first) */
    if (ctx->mask_u_contact >= 0 && memcmp(c, ctx->mask_contact, sizeof c) != 0) {
        memcpy(ctx->mask_contact, c, sizeof c);
        ctx->gl.Uniform4fv(ctx->mask_u_contact, 1, c);
    }
    if (d->contact_length > 0.0f && ctx->mask_u_view_proj >= 0) {
        sk_mat4 vp = sk_mat4_mul(rc->proj, rc->view);
        ctx->gl.UniformMatrix4fv(ctx->mask_u_view_proj, 1, 0, vp.m);
    }
}

SKGLDEF sk_result skgl_shadow_mask(skgl_context *ctx, skgl_shadow *s, const skgl_camera *cam,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex)
{
    skgl__st st;
    int w = 0, h = 0;
    sk_mat4 inv;
    double o[3];
    skgl_camera rc;
    skgl__cam ci;
    sk_result r;
    const char *fn = "skgl_shadow_mask";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_shadow_mask", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_shadow_mask"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, NULL, &ci));
    SKGL__TRY(skgl__arg_name(ctx, fn, depth_tex, "depth_tex"));
    SKGL__TRY(skgl__arg_name(ctx, fn, mask_tex, "mask_tex"));
    if (!s->rendered)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: s: the light has not been rendered yet (skgl_shadow_render "
                          "first)", fn);
    /* positions reconstructed relative to this camera's origin, from depth
       in the caller's convention (cam->proj, ci.dmap) */
    skgl__origin(&cam->view, o);
    rc = skgl__camera_rel(cam, o);
    if (!sk_mat4_inverse(sk_mat4_mul(rc.proj, rc.view), &inv))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj * cam->view is singular near this camera's "
                          "origin", fn);
    /* an EVSM light: the mask program with EVSM, under the context's mask_* names */
    if (s->desc.filter == SKGL_FILTER_EVSM) skgl__mask_swap(ctx);
    skgl__st_begin(ctx, &st);
    skgl__timer_begin(ctx, &s->t_mask);
    r = skgl__arg_texture(ctx, &st, fn, depth_tex, "depth_tex");
    if (r == SK_OK) r = skgl__arg_texture(ctx, &st, fn, normal_tex, "normal_tex");
    if (r == SK_OK) r = skgl__mask_begin(ctx, &st, mask_tex, &w, &h, "skgl_shadow_mask: mask_tex");
    if (r == SK_OK) {
        skgl__unitbind b[5];
        int n = skgl__mask_gbuffer(ctx, depth_tex, normal_tex, b);
        skgl__st_set1(ctx, &st, SKGL__S_SCISSOR_TEST, 0);
        if (skgl__technique_of(s)->mask) n += skgl__technique_of(s)->mask(s, b + n);
        else if (ctx->caps.webgl) skgl__bind_unit(&b[n++], 3, SKGL__T_2D, 0, 0);   /* see skgl__mask_gbuffer */
        skgl__bind_unit(&b[n++], 0, SKGL__T_2D_ARRAY, s->tex, ctx->cmp_sampler);
        /* EVSM: the moments on unit 4, bilinear through the texture's own filter */
        if (s->desc.filter == SKGL_FILTER_EVSM) skgl__bind_unit(&b[n++], 4, SKGL__T_2D_ARRAY, s->evsm.tex, 0);
        skgl__st_units(ctx, &st, b, n);
        skgl__st_set1(ctx, &st, SKGL__S_PROGRAM, (skgl__int)ctx->mask_prog);
        skgl__depth_map_send(&ctx->gl, ctx->mask_u_depth_map, ctx->mask_dmap, ci.dmap);
        skgl__shadow_uniforms(ctx, s, &ctx->mask_ent, 0, 3, o);
        if (ctx->mask_ent.has_normals != (normal_tex != 0)) {
            ctx->mask_ent.has_normals = normal_tex != 0;
            skgl__u1i(&ctx->gl, ctx->mask_u_has_normals, normal_tex != 0);
        }
        skgl__mask_camera(ctx, ctx->mask_u_camera, &inv, &rc.view);
        skgl__mask_contact(ctx, &s->desc, &rc);
        ctx->gl.DrawArrays(SKGL__TRIANGLES, 0, 3);
    }
    skgl__timer_end(ctx, &s->t_mask);
    s->stats.mask_ms = s->t_mask.ms;
    skgl__st_end(ctx, &st);
    if (s->desc.filter == SKGL_FILTER_EVSM) skgl__mask_swap(ctx);
    return r != SK_OK ? r : skgl__check(ctx, "skgl_shadow_mask");
}


/* ---- 7. Point lights: cube shadow maps and VSDCT (King & Newhall 2004) --- */
// >>point
#define SKGL__MAX_CUBE_MAP_TEXTURE_SIZE 0x851C

/* a point light's cache (7, the faces' cache): the faces' static depth, the
   light position and face side it holds, per face valid and equal to the
   map's face; the boxes invalidated since the last render; the scratch
   map of .verify_cache */
typedef struct skgl__point_cache {
    skgl__uint tex, fbo[6], verify_tex, verify_fbo;
    int fbo_level, m, all, ndirty;
    unsigned fresh;                /* the faces drawn whole this frame (bit f) */
    sk_vec3 pos;
    int valid[6], same[6], dyn[6][4];
    sk_aabb dirty[SKGL_CACHE_REGIONS];
    sk_mat4 spot_vp;               /* a spot: the light matrix its one face was drawn with */
} skgl__point_cache;

struct skgl_point {
    skgl_point_desc desc;
    unsigned id;                   /* per context, never reused: whose constants a program holds */
    skgl__uint tex;                /* cube map of depth (mip chain with .select_resolution) or the 2D atlas */
    skgl__uint indirection;        /* VSDCT: RG16 indirection cube map */
    skgl__uint prog;               /* the mask program, compiled for this technique */
    skgl__uint lin_sampler;        /* VSDCT: bilinear, no comparison (the indirection) */
    skgl__uint fbo[6];             /* cube: one framebuffer per face, at mip level fbo_level;
                                      VSDCT: [0] the light's own atlas's (a shared atlas has its own) */
    skgl__uint fbo_layered;        /* cube with desc.layered: all six faces, at fbo_level */
    int fbo_level;
    int tex_level;                 /* cube: the one mip level sampling reads (-1: not set yet) */
    skgl__progent ent;             /* the mask program's snippet uniforms */
    skgl__int u_has_normals, u_inv_view_proj;
    skgl__int u_depth_map;         /* the camera's depth convention, and its value last sent */
    float dmap[4];
    int levels;                    /* cube: mip levels allocated */
    int ni;                        /* VSDCT: indirection side, Eq. (5.4.7) */
    int filled_res;                /* VSDCT: face side the indirection holds (0: none yet) */
    int face_res, level;           /* side rendered by the last render; cube: its mip level */
    int rendered;                  /* 1 once a render succeeded */
    sk_vec3 light_pos;
    sk_frustum view;               /* camera frustum of the render under way (caster culling) */
    float cull_margin;             /* world distance casters are grown by when culled (the filter's reach) */
    sk_vsdct_layout layout;        /* VSDCT: faces at face_res inside the full-size atlas */
    unsigned layout_serial;        /* changes with layout (its rectangles in the snippet) */
    int packed;                    /* shared atlas: 1 once skgl_point_atlas_pack placed the faces */
    skgl__timer t_render, t_mask;
    skgl__point_cache cache;       /* desc.cache only */
    skgl_point_frame_stats stats;
    /* a spot (desc.spot_angle > 0): its axis, the map's window
       (sk_spot_window) and light-relative position -> clip matrix of the
       last render */
    sk_vec3 spot_axis;
    float spot_win[4];
    sk_mat4 spot_rel;
};

struct skgl_point_atlas {
    skgl__uint tex;                /* GL_TEXTURE_2D, DEPTH_COMPONENT32F, comparison on */
    skgl__uint fbo;                /* its framebuffer, checked when made */
    int w, h;
};

/* defined with the faces' passes (7, the faces' cache) */
#ifndef SKGL_NO_CACHE
static sk_result skgl__point_cache_create(skgl_context *ctx, skgl__st *st, skgl_point *p);
static void skgl__point_cache_free(skgl_context *ctx, skgl_point *p);
#endif
/* defined with the spot lights (7, SPOT LIGHTS) */
static int skgl__spot_caster_visible(skgl_point *p, sk_aabb caster, int info_dynamic);
static void skgl__spot_uniforms(skgl_context *ctx, const skgl_point *p, const skgl__int *L);

/* the 2D depth texture the light renders into and samples: shared or its own */
static skgl__uint skgl__point_tex(const skgl_point *p)
{
    return p->desc.atlas ? p->desc.atlas->tex : p->tex;
}

static skgl_point_desc skgl__point_defaults(const skgl_point_desc *d)
{
    skgl_point_desc r = *d;
    if (r.resolution == 0) r.resolution = 512;
    if (r.near_plane == 0.0f) r.near_plane = 0.05f;
    if (r.range == 0.0f) r.range = 10.0f;
    if (r.slope_bias == 0.0f) r.slope_bias = 2.0f;
    if (r.depth_bias == 0.0f) r.depth_bias = 1.0f;
    if (r.normal_bias == 0.0f && r.bias == SKGL_BIAS_NORMAL_OFFSET) r.normal_bias = 1.5f;
    if (r.plane_bias == 0.0f) r.plane_bias = 0.5f;
    if (r.pcf_radius == 0) r.pcf_radius = 1;
    if (r.bias == SKGL_BIAS_NONE) r.normal_bias = 0.0f;
    skgl__apply_switches(&r.slope_bias, &r.depth_bias, r.disable_polygon_offset, &r.plane_bias, r.disable_plane_bias,
                         &r.pcf_radius, r.disable_pcf_kernel);
    if (r.resolution_c == 0.0f) r.resolution_c = 2.0f;
    if (r.vsdct_grey_levels == 0) r.vsdct_grey_levels = 256;
    if (r.spot_angle > 0.0f) r.technique = SKGL_POINT_VSDCT;   /* a spot's one map: a 2D atlas rectangle */
    return r;
}

/* the faces at side m inside the atlas allocated for desc.resolution: the
   3 x 2 arrangement of sk_vsdct_layout_make, shrunk into the corner */
static sk_vsdct_layout skgl__point_layout(const skgl_point *p, int m)
{
    sk_vsdct_layout l;
    int f;
    sk_vsdct_layout_make(p->desc.resolution, &l);
    l.face_res = m;
    for (f = 0; f < 6; f++) { l.face_x[f] = (f % 3) * m; l.face_y[f] = (f / 3) * m; }
    if (p->desc.spot_angle > 0.0f) {   /* a spot: one face in the corner of its own map */
        l.atlas_w = l.atlas_h = p->desc.resolution;
        for (f = 0; f < 6; f++) l.face_x[f] = l.face_y[f] = 0;
    }
    return l;
}

/* VSDCT: (re)fills the indirection cube map for the faces of layout l
   (nothing to do when it already holds them; bound on unit 0 to upload) */
static sk_result skgl__point_fill(skgl_context *ctx, skgl__st *st, skgl_point *p, const sk_vsdct_layout *l)
{
    skgl__api *gl = &ctx->gl;
    size_t face_n = (size_t)p->ni * (size_t)p->ni * 2;
    unsigned short *buf;
    int f;
    if (p->filled_res != 0 && memcmp(&p->layout, l, sizeof *l) == 0) return SK_OK;
    /* SK_POINT_VSDCT_ANALYTIC: the shader maps the faces itself; a spot
       samples through its matrix */
    if (!ctx->caps.norm16 || p->desc.spot_angle > 0.0f) {
        p->layout = *l;
        p->layout_serial++;
        p->filled_res = l->face_res;
        return SK_OK;
    }
    buf = (unsigned short *)SKGL_MALLOC(sizeof(unsigned short) * face_n * 6);
    if (!buf) return SK_ERR_CAPACITY;
    if (sk_vsdct_indirection_fill(l, p->ni, buf) != SK_OK) { SKGL_FREE(buf); return SK_ERR_INVALID_ARG; }
    p->layout = *l;
    p->layout_serial++;
    skgl__st_unpack(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_CUBE), (skgl__int)p->indirection);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_CUBE));
    for (f = 0; f < 6; f++)
        gl->TexImage2D(SKGL__TEXTURE_CUBE_MAP_POSITIVE_X + (skgl__enum)f, 0, SKGL__RG16, p->ni, p->ni, 0, SKGL__RG,
                       SKGL__UNSIGNED_SHORT, buf + face_n * (size_t)f);
    SKGL_FREE(buf);
    p->filled_res = l->face_res;
    return SK_OK;
}

/* a VSDCT atlas: 2D depth, bilinear comparison on the texture itself (the
   masks sample it through no sampler object), made on unit 0 */
static void skgl__atlas_alloc(skgl_context *ctx, skgl__st *st, skgl__uint tex, int w, int h)
{
    skgl__api *gl = &ctx->gl;
    skgl__st_unpack(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_2D), (skgl__int)tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_2D));
    gl->TexImage2D(SKGL__TEXTURE_2D, 0, SKGL__DEPTH_COMPONENT32F, w, h, 0, SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_MIN_FILTER, SKGL__LINEAR);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_MAG_FILTER, SKGL__LINEAR);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_COMPARE_MODE, SKGL__COMPARE_REF_TO_TEXTURE);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_COMPARE_FUNC, SKGL__LEQUAL);
    /* GL's default wrap is GL_REPEAT: a bilinear tap at the atlas's edge
       would blend in the opposite edge's texels */
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_WRAP_S, SKGL__CLAMP_TO_EDGE);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_WRAP_T, SKGL__CLAMP_TO_EDGE);
}

static void skgl__point_free(skgl_context *ctx, skgl_point *p)
{
    skgl__api *gl = &ctx->gl;
    int f;
    skgl__delete_texture(ctx, &p->tex);
    skgl__delete_texture(ctx, &p->indirection);
    if (p->prog) { gl->DeleteProgram(p->prog); ctx->objects--; }
    if (p->lin_sampler) { gl->DeleteSamplers(1, &p->lin_sampler); ctx->objects--; }
    for (f = 0; f < 6; f++) skgl__delete_framebuffer(ctx, &p->fbo[f]);
    skgl__delete_framebuffer(ctx, &p->fbo_layered);
#ifndef SKGL_NO_CACHE
    skgl__point_cache_free(ctx, p);
#endif
    skgl__timer_free(ctx, &p->t_render);
    skgl__timer_free(ctx, &p->t_mask);
    p->prog = p->lin_sampler = 0;
}

/* cube: the six faces' framebuffers onto mip level `level` (made when
   missing), each checked complete; 1 when all are */
static int skgl__point_cube_fbos(skgl_context *ctx, skgl__st *st, skgl_point *p, int level)
{
    int f, ok = 1;
    for (f = 0; f < 6; f++) {
        if (!p->fbo[f]) {
            ctx->gl.GenFramebuffers(1, &p->fbo[f]);
            ctx->objects++;
            skgl__st_framebuffer(ctx, st, p->fbo[f]);   /* glReadBuffer: the read target's */
            skgl__draw_buffers_none(ctx);
            ctx->gl.ReadBuffer(SKGL__NONE);
        }
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)p->fbo[f]);
        ctx->gl.FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT,
                                     SKGL__TEXTURE_CUBE_MAP_POSITIVE_X + (skgl__enum)f, p->tex, level);
        ok &= ctx->gl.CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) == SKGL__FRAMEBUFFER_COMPLETE;
    }
    if (p->desc.layered) {   /* the whole cube: gl_Layer picks the face */
        if (!p->fbo_layered) {
            ctx->gl.GenFramebuffers(1, &p->fbo_layered);
            ctx->objects++;
            skgl__st_framebuffer(ctx, st, p->fbo_layered);
            skgl__draw_buffers_none(ctx);
            ctx->gl.ReadBuffer(SKGL__NONE);
        }
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)p->fbo_layered);
        ctx->gl.FramebufferTexture(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT, p->tex, level);
        ok &= ctx->gl.CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) == SKGL__FRAMEBUFFER_COMPLETE;
    }
    p->fbo_level = ok ? level : -1;
    return ok;
}

static int skgl__is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

/* every rule of a skgl_point_desc (defaults filled), in field order */
static sk_result skgl__point_validate(skgl_context *ctx, const skgl_point_desc *d)
{
    const char *fn = "skgl_point_create";
    SKGL__RULE(d->technique == SKGL_POINT_CUBE || d->technique == SKGL_POINT_VSDCT, fn, "technique", d->technique,
               "one of skgl_point_technique");
    SKGL__RULE(d->resolution >= 1, fn, "resolution", d->resolution, "1 or more");
    SKGL__RULE(d->technique != SKGL_POINT_CUBE || !d->select_resolution || skgl__is_pow2(d->resolution), fn,
               "resolution", d->resolution, "a power of two with select_resolution and SKGL_POINT_CUBE");
    SKGL__RULE(sk__finite(d->near_plane) && d->near_plane > 0.0f, fn, "near_plane", d->near_plane, "more than 0");
    SKGL__RULE(sk__finite(d->range) && d->range > d->near_plane, fn, "range", d->range, "more than near_plane");
    SKGL__TRY(skgl__bias_rules(ctx, fn, d->slope_bias, d->depth_bias, d->normal_bias, d->bias, d->plane_bias,
                               d->pcf_radius));
    SKGL__RULE(sk__finite(d->resolution_c) && d->resolution_c > 0.0f, fn, "resolution_c", d->resolution_c,
               "more than 0");
    SKGL__RULE(d->screen_w >= 0, fn, "screen_w", d->screen_w, "0 or more");
    SKGL__RULE(d->screen_h >= 0, fn, "screen_h", d->screen_h, "0 or more");
    /* G of King & Newhall's Eq. (5.4.7): a grey ramp needs two levels at
       least, and the RG16 indirection holds 16 bits */
    SKGL__RULE(d->vsdct_grey_levels >= 2 && d->vsdct_grey_levels <= 65536, fn, "vsdct_grey_levels",
               d->vsdct_grey_levels, "in 2..65536 (0: the default)");
    SKGL__RULE(d->cull_faces == 0 || d->cull_faces == 1, fn, "cull_faces", d->cull_faces, "0 or 1");
    SKGL__RULE(d->cull_casters == 0 || d->cull_casters == 1, fn, "cull_casters", d->cull_casters, "0 or 1");
    SKGL__RULE(d->scissor == 0 || d->scissor == 1, fn, "scissor", d->scissor, "0 or 1");
    SKGL__RULE(d->select_resolution == 0 || d->select_resolution == 1, fn, "select_resolution",
               d->select_resolution, "0 or 1");
    SKGL__RULE(d->layered == 0 || d->layered == 1, fn, "layered", d->layered, "0 or 1");
    SKGL__NEED(!d->layered || ctx->caps.geometry_shader, fn, "desc.layered", SKGL__GEOMETRY);
    SKGL__RULE(d->cache == 0 || d->cache == 1, fn, "cache", d->cache, "0 or 1");
#ifdef SKGL_NO_CACHE
    SKGL__RULE(!d->cache, fn, "cache", d->cache, "cached maps are compiled out (SKGL_NO_CACHE)");
#endif
    SKGL__RULE(!d->cache || !d->layered, fn, "cache", d->cache,
               "a cached light draws its faces a pass each: not with desc.layered");
    SKGL__RULE(!d->cache || !d->atlas, fn, "cache", d->cache,
               "a shared atlas's rectangles move with every pack: not with desc.atlas");
    SKGL__RULE(d->cache_budget_kb >= 0, fn, "cache_budget_kb", d->cache_budget_kb, "0 (no limit) or more");
    SKGL__RULE(d->verify_cache == 0 || (d->verify_cache == 1 && d->cache), fn, "verify_cache", d->verify_cache,
               "0, or 1 with desc.cache");
    SKGL__NEED(!d->verify_cache || ctx->caps.api == SKGL_API_GL33, fn, "desc.verify_cache",
               "depth read-backs (glReadPixels of GL_DEPTH_COMPONENT: desktop OpenGL)");
    SKGL__RULE(sk__finite(d->spot_angle) && d->spot_angle >= 0.0f && d->spot_angle <= 85.0f, fn, "spot_angle",
               d->spot_angle, "in [0, 85] degrees (0: omnidirectional)");
    if (d->atlas && d->technique != SKGL_POINT_VSDCT)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.atlas is set: only SKGL_POINT_VSDCT lives in an atlas", fn);
    if (d->atlas && !d->atlas->tex)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.atlas has no texture (destroyed?)", fn);
    return SK_OK;
}

SKGLDEF sk_result skgl_point_create(skgl_context *ctx, const skgl_point_desc *desc, skgl_point **out)
{
    static const char fn[] = "skgl_point_create";
    skgl__api *gl;
    skgl_point *p;
    skgl_point_desc d;
    skgl__st st;
    skgl__int max_size = 0;
    char *fs;
    size_t n;
    int f, lv;
    sk_result r = SK_OK;
    if (out) *out = NULL;
    SKGL__TRY(skgl__create_open(ctx, fn, !desc, !out));
    d = skgl__point_defaults(desc);
    r = skgl__point_validate(ctx, &d);
    if (r != SK_OK) return r;
    gl = &ctx->gl;
    gl->GetIntegerv(d.technique == SKGL_POINT_CUBE ? SKGL__MAX_CUBE_MAP_TEXTURE_SIZE : SKGL__MAX_TEXTURE_SIZE,
                    &max_size);
    /* a shared atlas bounds the side by packing (skgl_point_atlas_pack halves it) */
    if (d.technique == SKGL_POINT_CUBE || d.spot_angle > 0.0f ? d.resolution > max_size
                                                                : !d.atlas && d.resolution > max_size / 3)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_point_create: desc.resolution = %d: at most %d here (%s)",
                          d.resolution, d.technique == SKGL_POINT_CUBE ? max_size : max_size / 3,
                          d.technique == SKGL_POINT_CUBE ? "GL_MAX_CUBE_MAP_TEXTURE_SIZE"
                                                         : "a third of GL_MAX_TEXTURE_SIZE, the 3 x 2 atlas");
    p = (skgl_point *)skgl__create_alloc(ctx, fn, sizeof *p);
    if (!p) return SK_ERR_CAPACITY;
    p->desc = d;
    p->id = ++ctx->next_id;
    if (!p->id) p->id = ++ctx->next_id;
    p->tex_level = p->fbo_level = -1;
    /* the mask program: the technique's define, the snippet, the pass */
    n = strlen(skgl__glsl(SKGL__GLSL_POINT_SAMPLE_GLSL)) + 96;
    fs = (char *)SKGL_MALLOC(n);
    if (!fs) { SKGL_FREE(p); return skgl__fail(ctx, SK_ERR_CAPACITY, "skgl_point_create: out of memory"); }
    strcpy(fs, d.technique == SKGL_POINT_VSDCT ? "#define SK_POINT_VSDCT 1\n" : "#define SK_POINT_VSDCT 0\n");
    if (d.spot_angle > 0.0f) strcat(fs, "#define SK_POINT_SPOT 1\n");
    if (!ctx->caps.norm16) strcat(fs, "#define SK_POINT_VSDCT_ANALYTIC 1\n");
    strcat(fs, skgl__glsl(SKGL__GLSL_POINT_SAMPLE_GLSL));
    p->prog = skgl__program(ctx, skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT), fs, skgl__glsl(SKGL__GLSL_POINT_MASK_FRAG));
    SKGL_FREE(fs);
    if (!p->prog) { SKGL_FREE(p); return SK_ERR_GL; }
    skgl__st_begin(ctx, &st);
    skgl__timer_init(ctx, &p->t_render);
    skgl__timer_init(ctx, &p->t_mask);
    /* the mask program's locations, its G-buffer units (the light's
       constants follow at its first mask) */
    skgl__progent_lookup(ctx, &p->ent, p->prog, SKGL__PK_POINT, "");
    p->ent.has_normals = -1;
    p->u_has_normals = gl->GetUniformLocation(p->prog, "u_has_normals");
    p->u_inv_view_proj = gl->GetUniformLocation(p->prog, "u_inv_view_proj");
    skgl__st_set1(ctx, &st, SKGL__S_PROGRAM, (skgl__int)p->prog);
    p->u_depth_map = skgl__depth_map_init(gl, p->prog, p->dmap);
    skgl__u1i(gl, gl->GetUniformLocation(p->prog, "u_depth"), 1);
    skgl__u1i(gl, gl->GetUniformLocation(p->prog, "u_normals"), 2);
    if (!d.atlas) { gl->GenTextures(1, &p->tex); ctx->objects++; }
    if (d.technique == SKGL_POINT_CUBE) {
        /* the full mip chain only when a smaller level may be chosen */
        p->levels = 1;
        if (d.select_resolution) while ((d.resolution >> p->levels) >= 1) p->levels++;
        skgl__st_unpack(ctx, &st);
        skgl__st_set1(ctx, &st, SKGL__S_TEX(0, SKGL__T_CUBE), (skgl__int)p->tex);
        skgl__st_unit(ctx, &st, SKGL__S_TEX(0, SKGL__T_CUBE));
        for (lv = 0; lv < p->levels; lv++) {
            int s = d.resolution >> lv;
            for (f = 0; f < 6; f++)
                gl->TexImage2D(SKGL__TEXTURE_CUBE_MAP_POSITIVE_X + (skgl__enum)f, lv, SKGL__DEPTH_COMPONENT32F, s, s,
                               0, SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
        }
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_BASE_LEVEL, 0);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAX_LEVEL, p->levels - 1);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MIN_FILTER, SKGL__LINEAR);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAG_FILTER, SKGL__LINEAR);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_COMPARE_MODE, SKGL__COMPARE_REF_TO_TEXTURE);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_COMPARE_FUNC, SKGL__LEQUAL);
        /* edges clamped, as the comparison sampler has them (the default
           GL_REPEAT matters wherever seamless filtering is off) */
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_WRAP_S, SKGL__CLAMP_TO_EDGE);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_WRAP_T, SKGL__CLAMP_TO_EDGE);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_WRAP_R, SKGL__CLAMP_TO_EDGE);
        if (!skgl__point_cube_fbos(ctx, &st, p, 0)) {
            skgl__set_log(ctx, "skgl_point_create: point shadow framebuffer incomplete", NULL);
            r = SK_ERR_GL;
        }
    } else {
        if (!d.atlas) {
            /* a spot's one face, or the 3 x 2 faces */
            if (d.spot_angle > 0.0f) skgl__atlas_alloc(ctx, &st, p->tex, d.resolution, d.resolution);
            else skgl__atlas_alloc(ctx, &st, p->tex, 3 * d.resolution, 2 * d.resolution);
            p->fbo[0] = skgl__framebuffer(ctx, &st, 0, 0, p->tex, -1);
            if (!p->fbo[0]) {
                skgl__set_log(ctx, "skgl_point_create: point shadow framebuffer incomplete", NULL);
                r = SK_ERR_GL;
            }
        }
        /* Eq. (5.4.7) with D = 8 bits of filter weight precision; never below
           the face side, so the linear ramp of the filtered coordinates is
           clamped for at most half a shadow texel at a face edge */
        p->ni = sk_vsdct_indirection_size(d.resolution, d.vsdct_grey_levels, 8);
        if (p->ni < 1 && r == SK_OK) r = skgl__fail(ctx, SK_ERR_INVALID_ARG,
                                                 "skgl_point_create: desc.vsdct_grey_levels = %d: too few for "
                                                 "desc.resolution %d (Eq. 5.4.7 gives no indirection side)",
                                                 d.vsdct_grey_levels, d.resolution);
        gl->GenTextures(1, &p->indirection); ctx->objects++;
        skgl__st_set1(ctx, &st, SKGL__S_TEX(0, SKGL__T_CUBE), (skgl__int)p->indirection);
        skgl__st_unit(ctx, &st, SKGL__S_TEX(0, SKGL__T_CUBE));
        /* the texture's own sampling (the masks bind no sampler object):
           bilinear, edges clamped, one level */
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MIN_FILTER, SKGL__LINEAR);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAG_FILTER, SKGL__LINEAR);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAX_LEVEL, 0);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_WRAP_S, SKGL__CLAMP_TO_EDGE);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_WRAP_T, SKGL__CLAMP_TO_EDGE);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_WRAP_R, SKGL__CLAMP_TO_EDGE);
        if (r == SK_OK) {
            sk_vsdct_layout l = skgl__point_layout(p, d.resolution);
            r = skgl__point_fill(ctx, &st, p, &l);
        }
        gl->GenSamplers(1, &p->lin_sampler); ctx->objects++;
        gl->SamplerParameteri(p->lin_sampler, SKGL__TEXTURE_MIN_FILTER, SKGL__LINEAR);
        gl->SamplerParameteri(p->lin_sampler, SKGL__TEXTURE_MAG_FILTER, SKGL__LINEAR);
        gl->SamplerParameteri(p->lin_sampler, SKGL__TEXTURE_WRAP_S, SKGL__CLAMP_TO_EDGE);
        gl->SamplerParameteri(p->lin_sampler, SKGL__TEXTURE_WRAP_T, SKGL__CLAMP_TO_EDGE);
        gl->SamplerParameteri(p->lin_sampler, SKGL__TEXTURE_WRAP_R, SKGL__CLAMP_TO_EDGE);
        gl->SamplerParameteri(p->lin_sampler, SKGL__TEXTURE_COMPARE_MODE, SKGL__NONE);
    }
    p->face_res = d.resolution;
    p->layout = skgl__point_layout(p, d.resolution);
#ifndef SKGL_NO_CACHE
    if (r == SK_OK && d.cache) r = skgl__point_cache_create(ctx, &st, p);
#endif
    skgl__st_end(ctx, &st);
    r = skgl__create_close(ctx, fn, r, "the light's maps");
    if (r != SK_OK) {
        skgl_point_destroy(ctx, p);
        return r;
    }
    p->stats.shadow_ms = p->stats.mask_ms = -1.0f;
    *out = p;
    return SK_OK;
}

SKGLDEF void skgl_point_destroy(skgl_context *ctx, skgl_point *p)
{
    if (!ctx || !p) return;
    skgl__point_free(ctx, p);
    SKGL_FREE(p);
}
SKGLDEF skgl_point_desc skgl_point_get_desc(const skgl_point *p)
{
    skgl_point_desc d;
    if (p) return p->desc;
    memset(&d, 0, sizeof d);
    return d;
}
SKGLDEF const skgl_point_frame_stats *skgl_point_stats(const skgl_point *p) { return p ? &p->stats : NULL; }
SKGLDEF unsigned skgl_point_texture(const skgl_point *p)
{
    return p ? skgl__point_tex(p) : 0;
}
SKGLDEF sk_vsdct_layout skgl_point_layout(const skgl_point *p)
{
    sk_vsdct_layout l;
    if (p) return p->layout;
    memset(&l, 0, sizeof l);
    return l;
}

SKGLDEF const char *skgl_point_glsl_snippet(void) { return skgl__glsl(SKGL__GLSL_POINT_SAMPLE_GLSL); }

SKGLDEF int skgl_point_glsl_snippet_prefixed(const char *prefix, char *out, int cap)
{
    return skgl__glsl_prefixed(skgl__glsl(SKGL__GLSL_POINT_SAMPLE_GLSL), prefix, out, cap);
}

SKGLDEF int skgl_point_caster_visible(const skgl_draw_info *info, sk_aabb caster)
{
    skgl_point *p;
    int vis;
    if (!info || (info->kind != SKGL_PASS_CUBE_FACE && info->kind != SKGL_PASS_SPOT) || !info->point) return 1;
    p = info->point;
    if (!p->desc.cull_casters) return 1;
    if (info->kind == SKGL_PASS_SPOT) return skgl__spot_caster_visible(p, caster, info->dynamic);
    /* King & Newhall's caster culling: the light-to-box cone frustum (or the
       light's range box when the light is inside the box) against the view
       frustum; then the box against this face's frustum */
    if (sk__aabb_valid(&caster)) {   /* grown by the filter's reach at the light's range */
        caster.min = sk__sub(caster.min, sk__v3(p->cull_margin, p->cull_margin, p->cull_margin));
        caster.max = sk__add(caster.max, sk__v3(p->cull_margin, p->cull_margin, p->cull_margin));
    }
    /* a cached face keeps its static casters for every view: not culled by this one */
    vis = (p->cache.tex && !info->dynamic) || sk_caster_visible(info->light_pos, info->light_range, caster, &p->view);
    if (vis) {
        sk_frustum bf;
        int i;
        if (sk_frustum_from_aabb(caster, &bf) == SK_OK) {
            /* a layered pass: visible through any of its faces */
            if (info->layers > 0)
                for (i = 0, vis = 0; i < info->layers && !vis && i < SKGL_MAX_CASCADES; i++)
                    vis = sk_frustum_intersects(&bf, &info->layer_frustum[i]);
            else vis = sk_frustum_intersects(&bf, &info->frustum);
        }
    }
    if (vis) p->stats.casters_drawn++; else p->stats.casters_culled++;
    return vis;
}

/* The filter's reach in face-plane units (tangent of the angle off a
   receiver's light vector): the (2r)x(2r) taps, the hardware 2x2 under
   each, and the normal offset, at face side m. A face or caster that only
   such a tap can read is still needed for a visible pixel. */
static double skgl__point_reach(const skgl_point *p, int m)
{
    double nb = p->desc.normal_bias > 0.0f ? p->desc.normal_bias : 0.0;
    return (p->desc.pcf_radius + 1.0 + nb) * 2.0 / m;
}

/* sk_cube_visible_faces with each face frustum widened by `reach` (its
   half-width tangent 1 + reach instead of 1), so that the filter taps of a
   visible receiver near a face edge find the neighbouring face rendered */
static unsigned skgl__point_faces(sk_vec3 lp, float zn, float zf, const sk_frustum *view, double reach)
{
    unsigned bits = 0;
    int f;
    if (sk_frustum_contains_point(view, lp)) return 0x3fu;
    for (f = 0; f < 6; f++) {
        sk_mat4 proj = sk_cube_face_proj(zn, zf);
        sk_frustum ff;
        proj.m[0] = proj.m[5] = (float)(1.0 / (1.0 + reach));
        ff = sk_frustum_from_matrix(sk_mat4_mul(proj, sk_cube_face_view(f, lp)));
        if (sk_frustum_intersects(&ff, view)) bits |= 1u << f;
    }
    return bits;
}

static int skgl__popcount6(unsigned b)
{
    int f, n = 0;
    for (f = 0; f < 6; f++) n += (b >> f) & 1u;
    return n;
}

/* the sphere that bounds what the light reaches: its range sphere, or a
   spot's cone (half-angle a up to 60 degrees: the sphere through the apex
   and the rim of the cone's cap, centre range / (2 cos a) down the axis;
   wider cones: the range sphere, which is then smaller) */
static float skgl__light_bound(const skgl_point *p, sk_vec3 *centre)
{
    double c = p->desc.spot_angle > 0.0f ? SK_COS((double)p->desc.spot_angle * 3.14159265358979323846 / 180.0) : 0.0;
    *centre = p->light_pos;
    if (!(c >= 0.5) || !(sk__len(p->spot_axis) > 0.0f)) return p->desc.range;   /* (not aimed yet) */
    *centre = sk__add(p->light_pos, sk__scale(p->spot_axis, (float)(p->desc.range / (2.0 * c))));
    return (float)(p->desc.range / (2.0 * c));
}

/* the pixel count S of the light (its scissor rectangle on the screen) */
static float skgl__point_pixels(const skgl_point *p, const sk_mat4 *vp, const skgl__int viewport[4])
{
    int rect[4], w = p->desc.screen_w, h = p->desc.screen_h;
    if (w < 1 || h < 1) { w = viewport[2]; h = viewport[3]; }
    if (w < 1 || h < 1) return 0.0f;
    sk_vec3 c;
    float radius = skgl__light_bound(p, &c);
    if (!sk_light_scissor(c, radius, *vp, w, h, rect)) return 0.0f;
    return (float)rect[2] * (float)rect[3];
}

/* face culling: a face whose frustum misses the view frustum casts
   nothing visible (King & Newhall Fig. 5.4.2, frustum-frustum intersection), widened
   by the filter's reach at the face side m. Resolution selection: the
   smallest power of two M with N M^2 >= c S, N the faces rendered. A
   smaller M widens the reach, which may add faces, which may lower M:
   repeated until both hold (M only decreases). p->light_pos and p->view
   hold this frame's light and view. Returns M; *faces the faces' bits. */
static int skgl__point_select(const skgl_point *p, const sk_mat4 *vp, const skgl__int viewport[4], unsigned *faces)
{
    int f, nf, m = p->desc.resolution;
    for (f = 0; f < 8; f++) {
        int sel;
        *faces = p->desc.cull_faces ? skgl__point_faces(p->light_pos, p->desc.near_plane, p->desc.range, &p->view,
                                                        skgl__point_reach(p, m))
                                    : 0x3fu;
        nf = skgl__popcount6(*faces);
        if (!p->desc.select_resolution || nf == 0) break;
        sel = sk_cube_resolution(nf, skgl__point_pixels(p, vp, viewport), p->desc.resolution_c, p->desc.resolution);
        if (sel <= 0 || sel >= m) break;
        m = sel;
    }
    return m;
}

/* the caller's viewport (the resolution selection's screen when
   screen_w/screen_h are 0): the saved value in the default mode; read from
   GL in caller-owns mode, the one read that mode makes (set screen_w and
   screen_h to avoid it) */
static void skgl__caller_viewport(skgl_context *ctx, skgl__st *st, skgl__int v[4])
{
    if (st->restore) {
        skgl__st_save(ctx, st, SKGL__S_VIEWPORT);
        memcpy(v, st->orig[SKGL__S_VIEWPORT], sizeof(skgl__int) * 4);
    } else ctx->gl.GetIntegerv(SKGL__VIEWPORT, v);
}

/* the face side this frame and the faces to render: the side
   skgl_point_atlas_pack placed (a halved side reaches further, so it may
   add a face), or the selected one; the cube's mip level for it */
static int skgl__point_side(skgl_context *ctx, skgl__st *st, skgl_point *p, const sk_mat4 *vp, unsigned *faces)
{
    skgl__int viewport[4] = {0, 0, 0, 0};
    float zn = p->desc.near_plane, zf = p->desc.range;
    int m;
    if (p->desc.atlas) {
        m = p->layout.face_res;
        *faces = p->desc.cull_faces ? skgl__point_faces(p->light_pos, zn, zf, &p->view, skgl__point_reach(p, m))
                                    : 0x3fu;
    } else {
        if (p->desc.select_resolution && (p->desc.screen_w < 1 || p->desc.screen_h < 1))
            skgl__caller_viewport(ctx, st, viewport);
        m = skgl__point_select(p, vp, viewport, faces);
    }
    p->cull_margin = (float)(skgl__point_reach(p, m) * zf);
    p->level = 0;
    if (p->desc.technique == SKGL_POINT_VSDCT) return m;
    while ((p->desc.resolution >> p->level) > m) p->level++;
    return p->desc.resolution >> p->level;
}

/* what the faces render into at side m: an own VSDCT atlas's indirection
   for the layout, or the cube's level (sampled alone) and its framebuffers */
static sk_result skgl__point_target(skgl_context *ctx, skgl__st *st, skgl_point *p, int m)
{
    skgl__api *gl = &ctx->gl;
    if (p->desc.technique == SKGL_POINT_VSDCT) {
        sk_vsdct_layout l;
        if (p->desc.atlas) return SK_OK;   /* skgl_point_atlas_pack filled it */
        l = skgl__point_layout(p, m);
        return skgl__point_fill(ctx, st, p, &l);
    }
    /* sampling reads the level rendered, and only that one: set when it changes */
    if (p->tex_level != p->level) {
        skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_CUBE), (skgl__int)p->tex);
        skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_CUBE));
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_BASE_LEVEL, p->level);
        gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAX_LEVEL, p->level);
        p->tex_level = p->level;
    }
    /* the faces' framebuffers follow the level: attached and checked again when it changes */
    if (p->fbo_level != p->level && !skgl__point_cube_fbos(ctx, st, p, p->level))
        return skgl__fail(ctx, SK_ERR_GL, "skgl_point_render: a cube face's framebuffer is incomplete at level %d",
                          p->level);
    return SK_OK;
}

// >>point_cache
#ifndef SKGL_NO_CACHE
/* CACHED MAPS for point lights: the faces' static depth in
   a texture shaped like the light's own (a cube with the same levels, or
   the 3 x 2 atlas), valid while the light stays where it was at the same
   face side; invalidated boxes redrawn in each face's rectangle of their
   corners; a face culled this frame is cleared in the map and keeps its
   cache unless a box was invalidated while it was away. */
static double skgl__point_cache_bytes(const skgl_point *p)
{
    int lv;
    double b = 0.0;
    if (p->desc.spot_angle > 0.0f) return 4.0 * p->desc.resolution * p->desc.resolution;
    if (p->desc.technique == SKGL_POINT_VSDCT) return 4.0 * 6.0 * p->desc.resolution * p->desc.resolution;
    for (lv = 0; lv < p->levels; lv++) b += 4.0 * 6.0 * (double)(p->desc.resolution >> lv) * (p->desc.resolution >> lv);
    return b;
}

/* the cache's texture (at create, after the light's own) */
static sk_result skgl__point_cache_create(skgl_context *ctx, skgl__st *st, skgl_point *p)
{
    skgl__api *gl = &ctx->gl;
    skgl__point_cache *c = &p->cache;
    int f, lv;
    c->all = 1;
    c->fbo_level = -1;
    p->stats.cache_verify_texels = -1;
    p->stats.cache_bytes = skgl__point_cache_bytes(p);
    if (p->desc.cache_budget_kb > 0 && p->stats.cache_bytes > 1024.0 * p->desc.cache_budget_kb) {
        p->stats.cache_bytes = 0.0;   /* over the budget: drawn every frame */
        return SK_OK;
    }
    gl->GenTextures(1, &c->tex);
    ctx->objects++;
    if (p->desc.technique == SKGL_POINT_VSDCT) {   /* a spot's one face, or the 3 x 2 faces */
        int spot = p->desc.spot_angle > 0.0f;
        skgl__atlas_alloc(ctx, st, c->tex, (spot ? 1 : 3) * p->desc.resolution, (spot ? 1 : 2) * p->desc.resolution);
        c->fbo[0] = skgl__framebuffer(ctx, st, 0, 0, c->tex, -1);
        return c->fbo[0] ? SK_OK : skgl__fail(ctx, SK_ERR_GL, "skgl_point_create: cache framebuffer incomplete");
    }
    skgl__st_unpack(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_TEX(0, SKGL__T_CUBE), (skgl__int)c->tex);
    skgl__st_unit(ctx, st, SKGL__S_TEX(0, SKGL__T_CUBE));
    for (lv = 0; lv < p->levels; lv++)
        for (f = 0; f < 6; f++)
            gl->TexImage2D(SKGL__TEXTURE_CUBE_MAP_POSITIVE_X + (skgl__enum)f, lv, SKGL__DEPTH_COMPONENT32F,
                           p->desc.resolution >> lv, p->desc.resolution >> lv, 0, SKGL__DEPTH_COMPONENT, SKGL__FLOAT,
                           NULL);
    gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAX_LEVEL, p->levels - 1);
    gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST);
    gl->TexParameteri(SKGL__TEXTURE_CUBE_MAP, SKGL__TEXTURE_MAG_FILTER, SKGL__NEAREST);
    return SK_OK;
}

static void skgl__point_cache_free(skgl_context *ctx, skgl_point *p)
{
    int f;
    skgl__delete_texture(ctx, &p->cache.tex);
    skgl__delete_texture(ctx, &p->cache.verify_tex);
    for (f = 0; f < 6; f++) skgl__delete_framebuffer(ctx, &p->cache.fbo[f]);
    skgl__delete_framebuffer(ctx, &p->cache.verify_fbo);
}

/* a cube cache's face framebuffers onto the level the light renders */
static int skgl__point_cache_fbos(skgl_context *ctx, skgl__st *st, skgl_point *p)
{
    skgl__point_cache *c = &p->cache;
    int f, ok = 1;
    if (p->desc.technique == SKGL_POINT_VSDCT || c->fbo_level == p->level) return 1;
    for (f = 0; f < 6; f++) {
        if (!c->fbo[f]) {
            ctx->gl.GenFramebuffers(1, &c->fbo[f]);
            ctx->objects++;
            skgl__st_framebuffer(ctx, st, c->fbo[f]);
            skgl__draw_buffers_none(ctx);
            ctx->gl.ReadBuffer(SKGL__NONE);
        }
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)c->fbo[f]);
        ctx->gl.FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT,
                                     SKGL__TEXTURE_CUBE_MAP_POSITIVE_X + (skgl__enum)f, c->tex, p->level);
        ok &= ctx->gl.CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) == SKGL__FRAMEBUFFER_COMPLETE;
    }
    c->fbo_level = ok ? p->level : -1;
    return ok;
}
#endif /* SKGL_NO_CACHE */

SKGLDEF sk_result skgl_point_invalidate(skgl_context *ctx, skgl_point *p, const sk_aabb *box)
{
    const char *fn = "skgl_point_invalidate";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_point_invalidate", 0);
    SKGL__TRY(skgl__arg_ptr(ctx, fn, p, "p"));
    SKGL__TRY(skgl__arg_box(ctx, fn, box));
#ifndef SKGL_NO_CACHE   /* compiled out, no light has a cache: nothing to redraw */
    if (!p->cache.tex || p->cache.all) return SK_OK;
    if (!box) p->cache.all = 1;
    else skgl__dirty_add(p->cache.dirty, &p->cache.ndirty, box);
#endif
    return SK_OK;
}

#ifndef SKGL_NO_CACHE
/* one caster pass of a face into fb, scissored to rect (x, y, w, h) */
static sk_result skgl__point_face_pass(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                       int f, const sk_mat4 *vp, skgl__uint fb, const int *rect, int cls, int clear)
{
    skgl_draw_info info;
    memset(&info, 0, sizeof info);
    info.kind = SKGL_PASS_CUBE_FACE;
    info.index = f;
    info.light_pos = p->light_pos;
    info.light_range = p->desc.range;
    info.point = p;
    return skgl__cached_pass(ctx, st, scene, vp, skgl__zero3, fb, rect, 0, cls, clear, &info, &p->stats.passes,
                             &p->stats.texels);
}

/* the faces of a cached light (the non-layered loop of
   skgl__point_draw_faces, its caster pass state begun) */
static sk_result skgl__point_faces_cached(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                          unsigned faces, int m)
{
    skgl__point_cache *c = &p->cache;
    sk_mat4 proj = sk_cube_face_proj(p->desc.near_plane, p->desc.range), face_vp;
    int f, k, vsdct = p->desc.technique == SKGL_POINT_VSDCT;
    sk_result r = SK_OK, rc = SK_OK;
    if (!skgl__point_cache_fbos(ctx, st, p))
        return skgl__fail(ctx, SK_ERR_GL, "skgl_point_render: a cache face's framebuffer is incomplete at level %d",
                          p->level);
    /* the light moved or changed its face side: every face drawn anew */
    if (c->all || memcmp(&c->pos, &p->light_pos, sizeof c->pos) != 0 || c->m != m)
        for (f = 0; f < 6; f++) c->valid[f] = 0;
    p->stats.faces_reused = p->stats.cache_regions = 0;
    p->stats.cache_copied = 0.0;
    c->fresh = 0;
    for (f = 0; f < 6; f++) {
        int x0 = vsdct ? p->layout.face_x[f] : 0, y0 = vsdct ? p->layout.face_y[f] : 0, rect[4], nr;
        int rects[SKGL_CACHE_REGIONS][4];
        skgl__uint live = vsdct ? p->fbo[0] : p->fbo[f], cached = vsdct ? c->fbo[0] : c->fbo[f];
        double w[16];
        rect[0] = x0; rect[1] = y0; rect[2] = rect[3] = m;
        skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, x0, y0, m, m);
        if (!(faces & (1u << f))) {   /* culled: read as lit, as without a cache */
            skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)live);
            skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 1);
            skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, x0, y0, m, m);
            skgl__clear_depth(ctx);
            c->same[f] = 0;
            if (c->ndirty > 0) c->valid[f] = 0;
            p->stats.faces_culled++;
            continue;
        }
        face_vp = sk_mat4_mul(proj, sk_cube_face_view(f, p->light_pos));
        if (!c->valid[f]) {
            rc = skgl__point_face_pass(ctx, st, p, scene, f, &face_vp, cached, rect, SKGL__DRAW_STATIC, 1);
            c->valid[f] = rc == SK_OK;
            c->same[f] = 0;
            c->fresh |= 1u << f;
        } else {
            p->stats.faces_reused++;
            skgl__world_matrix(&face_vp, skgl__zero3, w);
            nr = skgl__dirty_rects(w, c->dirty, c->ndirty, m, rects);
            for (k = 0; k < nr && rc == SK_OK; k++) {
                rects[k][0] += x0;
                rects[k][1] += y0;
                rc = skgl__point_face_pass(ctx, st, p, scene, f, &face_vp, cached, rects[k], SKGL__DRAW_STATIC, 1);
                c->same[f] = 0;
                p->stats.cache_regions++;
            }
        }
        /* the face from the cache, as skgl__cache_dynamic does a layer */
        if (rc == SK_OK) {
            int *d = c->dyn[f], x = c->same[f] ? d[0] : x0, y = c->same[f] ? d[1] : y0;
            int cw = c->same[f] ? d[2] : m, ch = c->same[f] ? d[3] : m;
            if (cw > 0) skgl__blit_depth(ctx, st, cached, live, x, y, cw, ch, 0, 0);
            p->stats.cache_copied += (double)cw * ch;
            c->same[f] = 1;
            d[2] = d[3] = 0;
        }
        if (rc == SK_OK && ctx->dyn.draw) {
            int dr[4];
            memcpy(dr, rect, sizeof dr);
            skgl__world_matrix(&face_vp, skgl__zero3, w);
            if (!skgl__has_dynamic_bounds(&ctx->dyn.bounds) || skgl__cache_box_rect(w, &ctx->dyn.bounds, m, dr)) {
                if (skgl__has_dynamic_bounds(&ctx->dyn.bounds)) { dr[0] += x0; dr[1] += y0; }
                rc = skgl__point_face_pass(ctx, st, p, scene, f, &face_vp, live, dr, SKGL__DRAW_DYNAMIC, 0);
                memcpy(c->dyn[f], dr, sizeof dr);
            }
        }
        if (rc != SK_OK) { r = rc; c->valid[f] = 0; rc = SK_OK; }
        p->stats.faces_rendered++;
    }
    c->pos = p->light_pos;
    c->m = m;
    c->ndirty = 0;
    c->all = 0;
    return r;
}

/* .verify_cache for a point light: every face the view needs drawn with
   all its casters into a scratch map shaped like the light's (a face, or
   the 3 x 2 atlas, each face at its own place: the rasterizer's depth
   depends on the window position, skgl__page_pass), against the face the
   render left; the tolerance of skgl__verify_compare, of the face's texels. */
static sk_result skgl__point_verify(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                    unsigned faces, int m)
{
    skgl__point_cache *c = &p->cache;
    sk_mat4 proj = sk_cube_face_proj(p->desc.near_plane, p->desc.range), face_vp;
    int f, vsdct = p->desc.technique == SKGL_POINT_VSDCT, res = p->desc.resolution, bad = -1, runs = 0;
    size_t n = (size_t)m * (size_t)m;
    skgl__verify_count v[6];
    float *a, *b;
    sk_result r = skgl__verify_texture(ctx, st, &c->verify_tex, &c->verify_fbo, vsdct ? 3 * res : res,
                                       vsdct ? 2 * res : res, "skgl_point_render");
    if (r != SK_OK) return r;
    a = (float *)SKGL_MALLOC(n * sizeof *a);
    b = (float *)SKGL_MALLOC(n * sizeof *b);
    if (!a || !b) { SKGL_FREE(a); SKGL_FREE(b); return SK_ERR_CAPACITY; }
    memset(v, 0, sizeof v);
    for (f = 0; f < 6 && r == SK_OK; f++) {
        int rect[4];
        if (!(faces & (1u << f))) continue;
        rect[0] = vsdct ? p->layout.face_x[f] : 0;
        rect[1] = vsdct ? p->layout.face_y[f] : 0;
        rect[2] = rect[3] = m;
        face_vp = sk_mat4_mul(proj, sk_cube_face_view(f, p->light_pos));
        skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, rect[0], rect[1], m, m);
        r = skgl__point_face_pass(ctx, st, p, scene, f, &face_vp, c->verify_fbo, rect, SKGL__DRAW_ALL, 1);
        p->stats.passes -= skgl__pass_callbacks(ctx);   /* not the cache's work */
        p->stats.texels -= (double)n;
        skgl__verify_read(ctx, st, vsdct ? p->fbo[0] : p->fbo[f], rect[0], rect[1], m, m, a);
        skgl__verify_read(ctx, st, c->verify_fbo, rect[0], rect[1], m, m, b);
        skgl__verify_compare(a, b, m, m, &v[f]);
        if (v[f].runs > runs) { runs = v[f].runs; bad = f; }
    }
    SKGL_FREE(a);
    SKGL_FREE(b);
    p->stats.cache_verify_texels = runs;
    if (r == SK_OK && runs > (int)(SKGL__VERIFY_RUNS * (double)n))
        r = skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_point_render: desc.verify_cache: face %d (%s this frame) "
                       "differs from the uncached face in %d texels side by side, by up to %g in depth: a caster "
                       "scene.draw draws changed without skgl_point_invalidate (moving casters belong in "
                       "skgl_set_dynamic, inside its bounds); %d texels alone, float rounding, accepted",
                       bad, c->fresh & (1u << bad) ? "drawn whole" : "kept", runs, (double)v[bad].worst, v[bad].alone);
    return r;
}
#endif /* SKGL_NO_CACHE */

/* the caster pass of each face in `faces` at side m (Eq. (5.4.6)'s window
   depth: 90 degrees, w = eye depth); every face is cleared, culled ones
   too: a filter tap near a visible face's edge may step into one, and must
   read "lit" there */
static sk_result skgl__point_draw_faces(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                        unsigned faces, int m)
{
    sk_mat4 proj = sk_cube_face_proj(p->desc.near_plane, p->desc.range), face_vp;
    int f, vsdct = p->desc.technique == SKGL_POINT_VSDCT, shared = p->desc.atlas != NULL;
    int layered = !vsdct && p->desc.layered && p->fbo_layered && skgl__layered_ready(ctx);
    sk_result r = SK_OK, rc;
    if (layered) skgl__casters_begin_layered(ctx, st, p->desc.slope_bias, p->desc.depth_bias, skgl__zero3);
    else skgl__casters_begin(ctx, st, p->desc.slope_bias, p->desc.depth_bias, skgl__zero3);
#ifndef SKGL_NO_CACHE
    if (p->cache.tex) {
        r = skgl__point_faces_cached(ctx, st, p, scene, faces, m);
        if (r == SK_OK && p->desc.verify_cache) r = skgl__point_verify(ctx, st, p, scene, faces, m);
        skgl__model_end(ctx);
        return r;
    }
#endif
    if (vsdct) {
        /* the faces' region of an own atlas, one clear; in a shared atlas
           each face's rectangle, cleared in the loop (the other lights'
           faces stay) */
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)(shared ? p->desc.atlas->fbo : p->fbo[0]));
        skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 1);
        if (!shared) {
            skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, 0, 0, 3 * m, 2 * m);
            skgl__clear_depth(ctx);
        }
    } else {
        skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
        skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, m, m);
    }
    p->stats.layered = 0;
    if (layered) {
        /* the faces the view needs in one pass (LAYERED PASSES) */
        sk_mat4 vps[6];
        int of[6], n = 0;
        skgl_draw_info info;
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)p->fbo_layered);
        skgl__clear_depth(ctx);   /* all six faces */
        for (f = 0; f < 6; f++) {
            if (!(faces & (1u << f))) { p->stats.faces_culled++; continue; }
            vps[n] = sk_mat4_mul(proj, sk_cube_face_view(f, p->light_pos));
            of[n++] = f;
        }
        p->stats.layered = ctx->layered_state;
        if (n > 0) {
            memset(&info, 0, sizeof info);
            info.kind = SKGL_PASS_CUBE_FACE;
            info.light_pos = p->light_pos;
            info.light_range = p->desc.range;
            info.point = p;
            r = skgl__casters_draw_layered(ctx, st, scene, vps, of, n, skgl__zero3, &info);
            p->stats.passes = skgl__pass_callbacks(ctx);
            p->stats.faces_rendered = n;
            p->stats.texels += (double)n * m * m;
        }
        skgl__model_end(ctx);
        return r;
    }
    for (f = 0; f < 6; f++) {
        skgl_draw_info info;
        if (vsdct) {
            skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, p->layout.face_x[f], p->layout.face_y[f], m, m);
            skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, p->layout.face_x[f], p->layout.face_y[f], m, m);
            if (shared) skgl__clear_depth(ctx);
        } else {
            skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)p->fbo[f]);
            skgl__clear_depth(ctx);
        }
        if (!(faces & (1u << f))) { p->stats.faces_culled++; continue; }
        memset(&info, 0, sizeof info);
        info.kind = SKGL_PASS_CUBE_FACE;
        info.index = f;
        info.light_pos = p->light_pos;
        info.light_range = p->desc.range;
        info.point = p;
        face_vp = sk_mat4_mul(proj, sk_cube_face_view(f, p->light_pos));
        rc = skgl__casters_draw(ctx, st, scene, &face_vp, skgl__zero3, &info);
        if (rc != SK_OK) r = rc;
        p->stats.passes += skgl__pass_callbacks(ctx);
        p->stats.faces_rendered++;
        p->stats.texels += (double)m * m;
    }
    skgl__model_end(ctx);
    return r;
}

static sk_result skgl__point_render_body(skgl_context *ctx, skgl_point *p, const skgl_camera *cam,
                                    const skgl_scene *scene, sk_vec3 light_pos)
{
    skgl__st st;
    sk_mat4 vp;
    unsigned faces = 0;
    int m;
    sk_result r;
    const char *fn = "skgl_point_render";
    skgl__cam ci;
    SKGL__TRY(skgl__arg_ptr(ctx, fn, p, "p"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, scene ? &scene->bounds : NULL, &ci));
    cam = &ci.gl;   /* OpenGL's convention from here on */
    SKGL__TRY(skgl__arg_scene(ctx, fn, scene, 1));
    SKGL__TRY(skgl__arg_vec(ctx, fn, light_pos, "light_pos", 0));
    if (p->desc.atlas && !p->packed)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: a shared-atlas light needs skgl_point_atlas_pack first", fn);
    if (p->desc.spot_angle > 0.0f)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.spot_angle = %g: a spot light renders with "
                          "skgl_spot_render", fn, (double)p->desc.spot_angle);
    vp = sk_mat4_mul(cam->proj, cam->view);
    p->light_pos = light_pos;
    p->view = sk_frustum_from_matrix(vp);
    skgl__st_begin(ctx, &st);
    m = skgl__point_side(ctx, &st, p, &vp, &faces);
    r = skgl__point_target(ctx, &st, p, m);
    if (r != SK_OK) { skgl__st_end(ctx, &st); return r; }
    p->face_res = m;
    p->stats.passes = p->stats.faces_rendered = p->stats.faces_culled = 0;
    p->stats.casters_drawn = p->stats.casters_culled = 0;
    p->stats.texels = 0.0;
    skgl__timer_begin(ctx, &p->t_render);
    r = skgl__point_draw_faces(ctx, &st, p, scene, faces, m);
    skgl__timer_end(ctx, &p->t_render);
    p->stats.shadow_ms = p->t_render.ms;
    p->stats.resolution = m;
    p->rendered = 1;
    skgl__st_end(ctx, &st);
    return r != SK_OK ? r : skgl__check(ctx, "skgl_point_render");
}

SKGLDEF sk_result skgl_point_render(skgl_context *ctx, skgl_point *p, const skgl_camera *cam,
                                    const skgl_scene *scene, sk_vec3 light_pos)
{
    sk_result r;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_point_render", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_point_render"));
    skgl__clip_depth(ctx, 0);   /* the passes under OpenGL's clip depth (CAMERA CONVENTIONS) */
    r = skgl__point_render_body(ctx, p, cam, scene, light_pos);
    skgl__clip_depth(ctx, 1);
    return skgl__said(ctx, "skgl_point_render", r, NULL);
}

/* The point snippet's uniforms on the current program (entry e), as
   skgl__shadow_uniforms: the light's constants when the program holds
   another's, the face size and the atlas rectangles when they changed, the
   light's position always. */
static void skgl__point_uniforms(skgl_context *ctx, const skgl_point *p, skgl__progent *e, int unit, int ind_unit)
{
    const skgl__api *gl = &ctx->gl;
    const skgl__int *L = e->loc;
    /* one texel at MA = 1: a cube face spans 2 there, a spot's map its window */
    float texel = (p->desc.spot_angle > 0.0f ? p->spot_win[2] - p->spot_win[0] : 2.0f) / (float)p->face_res;
    if (e->owner != p->id || e->unit != unit) {
        float scale, bias, depth[2];
        sk_vsdct_depth_coeffs(p->desc.near_plane, p->desc.range, &scale, &bias);
        depth[0] = scale; depth[1] = bias;
        skgl__u1i(gl, L[SKGL__P_CUBE], unit);
        skgl__u1i(gl, L[SKGL__P_ATLAS], unit);
        skgl__u1i(gl, L[SKGL__P_INDIRECTION], ind_unit);
        skgl__u1f(gl, L[SKGL__P_RANGE], p->desc.range);
        if (L[SKGL__P_DEPTH] >= 0) gl->Uniform2fv(L[SKGL__P_DEPTH], 1, depth);
        skgl__u1f(gl, L[SKGL__P_NORMAL_BIAS], p->desc.normal_bias > 0.0f ? p->desc.normal_bias : 0.0f);
        skgl__u1i(gl, L[SKGL__P_PCF], p->desc.pcf_radius);
        skgl__u1i(gl, L[SKGL__P_BIAS_MODE], p->desc.bias == SKGL_BIAS_RECEIVER_PLANE ? 0 : 1);
        skgl__u1f(gl, L[SKGL__P_PLANE_BIAS], p->desc.plane_bias > 0.0f ? p->desc.plane_bias : 0.0f);
        e->owner = p->id;
        e->unit = unit;
        e->sentinel_f = p->desc.range;
        e->texel = -1.0f;
        e->layout = 0;
    }
    if (e->texel != texel) { e->texel = texel; skgl__u1f(gl, L[SKGL__P_TEXEL], texel); }
    if (p->desc.technique == SKGL_POINT_VSDCT && e->layout != p->layout_serial && L[SKGL__P_FACES] >= 0) {
        float rects[24];
        int f;
        for (f = 0; f < 6; f++) {
            const sk_vsdct_layout *l = &p->layout;
            rects[4 * f + 0] = (float)((l->face_x[f] + 0.5) / l->atlas_w);
            rects[4 * f + 1] = (float)((l->face_y[f] + 0.5) / l->atlas_h);
            rects[4 * f + 2] = (float)((l->face_x[f] + l->face_res - 0.5) / l->atlas_w);
            rects[4 * f + 3] = (float)((l->face_y[f] + l->face_res - 0.5) / l->atlas_h);
        }
        gl->Uniform4fv(L[SKGL__P_FACES], 6, rects);
        e->layout = p->layout_serial;
    }
    if (L[SKGL__P_POS] >= 0) gl->Uniform3fv(L[SKGL__P_POS], 1, &p->light_pos.x);
    if (p->desc.spot_angle > 0.0f) skgl__spot_uniforms(ctx, p, L);
}

SKGLDEF sk_result skgl_point_bind(skgl_context *ctx, const skgl_point *p, unsigned program, int unit)
{
    return skgl_point_bind_named(ctx, p, program, unit, NULL);
}

SKGLDEF sk_result skgl_point_bind_named(skgl_context *ctx, const skgl_point *p, unsigned program, int unit,
                                        const char *prefix)
{
    skgl__api *gl;
    skgl__int active, last;
    skgl__progent *e;
    const char *fn = "skgl_point_bind";
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_point_bind_named", 0);
    SKGL__TRY(skgl__arg_ptr(ctx, fn, p, "p"));
    SKGL__TRY(skgl__arg_prefix(ctx, fn, prefix));
    SKGL__TRY(skgl__arg_name(ctx, fn, program, "program"));
    SKGL__TRY(skgl__arg_unit(ctx, fn, unit, 30));
    if (!p->rendered) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: the light has not been rendered yet", fn);
    SKGL__TRY(skgl__arg_program(ctx, fn, program));
    e = skgl__user_program(ctx, program, SKGL__PK_POINT, prefix ? prefix : "");
    if (p->desc.technique == SKGL_POINT_VSDCT)
        SKGL__TRY(skgl__snippet_present(ctx, fn, e, SKGL__P_ATLAS, program, prefix, "sk_point_atlas"));
    else SKGL__TRY(skgl__snippet_present(ctx, fn, e, SKGL__P_CUBE, program, prefix, "sk_point_cube"));
    gl = &ctx->gl;
    active = skgl__bind_active(ctx);
    last = SKGL__TEXTURE0 + unit;
    if (active != last) gl->ActiveTexture((skgl__enum)last);
    if (p->desc.technique == SKGL_POINT_VSDCT) {
        gl->BindTexture(SKGL__TEXTURE_2D, skgl__point_tex(p));
        gl->BindSampler((skgl__uint)unit, ctx->cmp_sampler);
        last = SKGL__TEXTURE0 + unit + 1;
        gl->ActiveTexture((skgl__enum)last);
        gl->BindTexture(SKGL__TEXTURE_CUBE_MAP, p->indirection);
        gl->BindSampler((skgl__uint)unit + 1, p->lin_sampler);
    } else {
        gl->BindTexture(SKGL__TEXTURE_CUBE_MAP, p->tex);
        gl->BindSampler((skgl__uint)unit, ctx->cmp_sampler);
    }
    if (active >= 0 && active != last) gl->ActiveTexture((skgl__enum)active);
    skgl__point_uniforms(ctx, p, e, unit, unit + 1);
    return skgl__check(ctx, "skgl_point_bind");
}

SKGLDEF sk_result skgl_point_mask(skgl_context *ctx, skgl_point *p, const skgl_camera *cam,
                                  unsigned depth_tex, unsigned normal_tex, unsigned mask_tex)
{
    skgl__st st;
    skgl__unitbind b[4];
    int w = 0, h = 0, vsdct, n;
    sk_mat4 vp, inv;
    int rect[4];
    sk_vec3 bound_c;
    float bound_r;
    sk_result r;
    const char *why;
    const char *fn = "skgl_point_mask";
    skgl__cam ci;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_point_mask", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_point_mask"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, p, "p"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, NULL, &ci));
    SKGL__TRY(skgl__arg_name(ctx, fn, depth_tex, "depth_tex"));
    SKGL__TRY(skgl__arg_name(ctx, fn, mask_tex, "mask_tex"));
    if (!p->rendered) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: the light has not been rendered yet", fn);
    /* depth read in the caller's convention (cam->proj, ci.dmap); the
       scissor from the camera in OpenGL's */
    if (!sk_mat4_inverse(sk_mat4_mul(cam->proj, cam->view), &inv))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj * cam->view is singular", fn);
    vp = sk_mat4_mul(ci.gl.proj, ci.gl.view);
    vsdct = p->desc.technique == SKGL_POINT_VSDCT;
    skgl__st_begin(ctx, &st);
    r = skgl__arg_texture(ctx, &st, fn, depth_tex, "depth_tex");
    if (r == SK_OK) r = skgl__arg_texture(ctx, &st, fn, normal_tex, "normal_tex");
    if (r != SK_OK) {
        skgl__st_end(ctx, &st);
        return r;
    }
    why = skgl__texture_size(ctx, &st, mask_tex, &w, &h);
    if (why) {
        skgl__st_end(ctx, &st);
        skgl__set_log(ctx, "skgl_point_mask: mask_tex", why);
        return SK_ERR_INVALID_ARG;
    }
    /* King & Newhall's scissor: the light's range box (a spot's: its cone's
       sphere's box) on the screen; the whole viewport when the eye is
       inside it (sk_light_scissor) */
    rect[0] = rect[1] = 0; rect[2] = w; rect[3] = h;
    bound_r = skgl__light_bound(p, &bound_c);
    if (p->desc.scissor && !sk_light_scissor(bound_c, bound_r, vp, w, h, rect)) {
        memset(p->stats.scissor, 0, sizeof p->stats.scissor);
        p->stats.mask_ms = ctx->timing ? 0.0f : -1.0f;
        skgl__st_end(ctx, &st);
        return skgl__check(ctx, "skgl_point_mask");
    }
    memcpy(p->stats.scissor, rect, sizeof rect);
    skgl__timer_begin(ctx, &p->t_mask);
    r = skgl__mask_begin(ctx, &st, mask_tex, &w, &h, "skgl_point_mask: mask_tex");
    if (r == SK_OK) {
        if (p->desc.scissor) {
            skgl__st_set1(ctx, &st, SKGL__S_SCISSOR_TEST, 1);
            skgl__st_set4(ctx, &st, SKGL__S_SCISSOR_BOX, rect[0], rect[1], rect[2], rect[3]);
        } else skgl__st_set1(ctx, &st, SKGL__S_SCISSOR_TEST, 0);
        /* cube: 2x2 filtering walks across face edges; VSDCT: the indirection
           must never blend two faces' coordinates */
        skgl__st_set1(ctx, &st, SKGL__S_SEAMLESS, !vsdct);
        /* the map and the indirection through their own texture parameters
           (comparison, filtering), no sampler object */
        n = skgl__mask_gbuffer(ctx, depth_tex, normal_tex, b);
        if (vsdct) skgl__bind_unit(&b[n++], 3, SKGL__T_CUBE, p->indirection, 0);
        skgl__bind_unit(&b[n++], 0, vsdct ? SKGL__T_2D : SKGL__T_CUBE, vsdct ? skgl__point_tex(p) : p->tex, 0);
        skgl__st_units(ctx, &st, b, n);
        skgl__st_set1(ctx, &st, SKGL__S_PROGRAM, (skgl__int)p->prog);
        skgl__point_uniforms(ctx, p, &p->ent, 0, 3);
        if (p->ent.has_normals != (normal_tex != 0)) {
            p->ent.has_normals = normal_tex != 0;
            skgl__u1i(&ctx->gl, p->u_has_normals, normal_tex != 0);
        }
        if (p->u_inv_view_proj >= 0) ctx->gl.UniformMatrix4fv(p->u_inv_view_proj, 1, 0, inv.m);
        skgl__depth_map_send(&ctx->gl, p->u_depth_map, p->dmap, ci.dmap);
        ctx->gl.DrawArrays(SKGL__TRIANGLES, 0, 3);
    }
    skgl__timer_end(ctx, &p->t_mask);
    p->stats.mask_ms = p->t_mask.ms;
    skgl__st_end(ctx, &st);
    return r != SK_OK ? r : skgl__check(ctx, "skgl_point_mask");
}


/* ---- Spot lights: a point light with a cone, one perspective map -------- */
// >>spot
static double skgl__spot_radians(const skgl_point *p) { return (double)p->desc.spot_angle * 3.14159265358979323846 / 180.0; }

/* caster culling for a spot: the box (grown by the filter's reach) against
   the cone, then its shadow frustum against the view (King & Newhall's
   caster culling with the cone in place of the faces) */
static int skgl__spot_caster_visible(skgl_point *p, sk_aabb caster, int info_dynamic)
{
    int vis;
    if (sk__aabb_valid(&caster)) {
        caster.min = sk__sub(caster.min, sk__v3(p->cull_margin, p->cull_margin, p->cull_margin));
        caster.max = sk__add(caster.max, sk__v3(p->cull_margin, p->cull_margin, p->cull_margin));
    }
    /* a cached spot keeps its static casters for every view that leaves
       its window as it is: culled by the cone only */
    vis = sk_spot_box_visible(p->light_pos, p->spot_axis, (float)skgl__spot_radians(p), p->desc.range, caster) &&
          ((p->cache.tex && !info_dynamic) || sk_caster_visible(p->light_pos, p->desc.range, caster, &p->view));
    if (vis) p->stats.casters_drawn++; else p->stats.casters_culled++;
    return vis;
}

/* the spot's own uniforms (SK_POINT_SPOT): its matrix, basis and cone,
   sent with every bind (the axis may move every frame) */
static void skgl__spot_uniforms(skgl_context *ctx, const skgl_point *p, const skgl__int *L)
{
    const skgl__api *gl = &ctx->gl;
    sk_vec3 o = sk__v3(0.0f, 0.0f, 0.0f);
    sk_mat4 v = sk_spot_view(o, p->spot_axis);
    /* columns right, up, axis: the view's rows, the axis its -z row negated
       (a mat4: the loader has no glUniformMatrix3fv) */
    float basis[16];
    memset(basis, 0, sizeof basis);
    basis[0] = v.m[0]; basis[1] = v.m[4]; basis[2] = v.m[8];
    basis[4] = v.m[1]; basis[5] = v.m[5]; basis[6] = v.m[9];
    basis[8] = -v.m[2]; basis[9] = -v.m[6]; basis[10] = -v.m[10];
    if (L[SKGL__P_SPOT] >= 0) gl->UniformMatrix4fv(L[SKGL__P_SPOT], 1, 0, p->spot_rel.m);
    if (L[SKGL__P_BASIS] >= 0) gl->UniformMatrix4fv(L[SKGL__P_BASIS], 1, 0, basis);
    skgl__u1f(gl, L[SKGL__P_COS], (float)SK_COS(skgl__spot_radians(p)));
}

/* the map's side this frame: .resolution, or King & Newhall's selection
   for one face (N = 1: M^2 >= c S, S the pixels of the light's rectangle) */
static int skgl__spot_select(const skgl_point *p, const sk_mat4 *vp, const skgl__int viewport[4])
{
    int sel;
    if (!p->desc.select_resolution) return p->desc.resolution;
    sel = sk_cube_resolution(1, skgl__point_pixels(p, vp, viewport), p->desc.resolution_c, p->desc.resolution);
    return sel > 0 ? sel : p->desc.resolution;
}

/* this frame's side: the one skgl_point_atlas_pack placed, or selected */
static int skgl__spot_side(skgl_context *ctx, skgl__st *st, skgl_point *p, const sk_mat4 *vp)
{
    skgl__int viewport[4] = {0, 0, 0, 0};
    if (p->desc.atlas) return p->layout.face_res;
    if (p->desc.select_resolution && (p->desc.screen_w < 1 || p->desc.screen_h < 1))
        skgl__caller_viewport(ctx, st, viewport);
    return skgl__spot_select(p, vp, viewport);
}

#ifndef SKGL_NO_CACHE
/* one caster pass of a cached spot into fb, scissored to rect (x, y, w, h) */
static sk_result skgl__spot_pass(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                 const sk_mat4 *light_vp, skgl__uint fb, const int *rect, int cls, int clear)
{
    skgl_draw_info info;
    memset(&info, 0, sizeof info);
    info.kind = SKGL_PASS_SPOT;
    info.light_pos = p->light_pos;
    info.light_range = p->desc.range;
    info.point = p;
    return skgl__cached_pass(ctx, st, scene, light_vp, skgl__zero3, fb, rect, 0, cls, clear, &info, &p->stats.passes,
                             &p->stats.texels);
}

/* CACHED MAPS for a spot: its one face's static depth, kept while the light
   matrix (position, axis, window: sk_spot_window's snapped window changes
   only when the view's part of the cone does) and the side stay as they
   were drawn; invalidated boxes redrawn in their rectangles; the dynamic
   casters drawn over a copy each frame. As skgl__point_faces_cached does a
   face. A frame whose view sees none of the cone (fit 0) clears the map
   and keeps the cache, unless a box was invalidated meanwhile. */
static sk_result skgl__spot_draw_cached(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                        const sk_mat4 *light_vp, int m, int fit)
{
    skgl__point_cache *c = &p->cache;
    int rect[4] = {0, 0, 0, 0}, rects[SKGL_CACHE_REGIONS][4], k, nr;
    double w[16];
    sk_result r = SK_OK;
    rect[2] = rect[3] = m;
    if (c->all || c->m != m || memcmp(&c->spot_vp, light_vp, sizeof c->spot_vp) != 0) c->valid[0] = 0;
    p->stats.faces_reused = p->stats.cache_regions = 0;
    p->stats.cache_copied = 0.0;
    c->fresh = 0;
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, m, m);
    if (fit != 1) {   /* read as lit, as without a cache */
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)p->fbo[0]);
        skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 1);
        skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, 0, 0, m, m);
        skgl__clear_depth(ctx);
        c->same[0] = 0;
        if (c->ndirty > 0) c->valid[0] = 0;
        c->ndirty = 0;
        p->stats.faces_culled = 1;
        return SK_OK;
    }
    if (!c->valid[0]) {
        r = skgl__spot_pass(ctx, st, p, scene, light_vp, c->fbo[0], rect, SKGL__DRAW_STATIC, 1);
        c->valid[0] = r == SK_OK;
        c->same[0] = 0;
        c->fresh = 1u;
    } else {
        p->stats.faces_reused = 1;
        skgl__world_matrix(light_vp, skgl__zero3, w);
        nr = skgl__dirty_rects(w, c->dirty, c->ndirty, m, rects);
        for (k = 0; k < nr && r == SK_OK; k++) {
            r = skgl__spot_pass(ctx, st, p, scene, light_vp, c->fbo[0], rects[k], SKGL__DRAW_STATIC, 1);
            c->same[0] = 0;
            p->stats.cache_regions++;
        }
    }
    /* the map from the cache: whole, or only what last frame's dynamic
       casters covered when the cache did not change */
    if (r == SK_OK) {
        int *d = c->dyn[0], x = c->same[0] ? d[0] : 0, y = c->same[0] ? d[1] : 0;
        int cw = c->same[0] ? d[2] : m, ch = c->same[0] ? d[3] : m;
        if (cw > 0) skgl__blit_depth(ctx, st, c->fbo[0], p->fbo[0], x, y, cw, ch, 0, 0);
        p->stats.cache_copied += (double)cw * ch;
        c->same[0] = 1;
        d[2] = d[3] = 0;
    }
    if (r == SK_OK && ctx->dyn.draw) {
        int dr[4];
        memcpy(dr, rect, sizeof dr);
        skgl__world_matrix(light_vp, skgl__zero3, w);
        if (!skgl__has_dynamic_bounds(&ctx->dyn.bounds) || skgl__cache_box_rect(w, &ctx->dyn.bounds, m, dr)) {
            r = skgl__spot_pass(ctx, st, p, scene, light_vp, p->fbo[0], dr, SKGL__DRAW_DYNAMIC, 0);
            memcpy(c->dyn[0], dr, sizeof dr);
        }
    }
    if (r != SK_OK) c->valid[0] = 0;
    p->stats.faces_rendered = 1;
    c->spot_vp = *light_vp;
    c->m = m;
    c->ndirty = 0;
    c->all = 0;
    return r;
}

/* .verify_cache for a spot: its face drawn with all its casters into a
   scratch map of the same size, at the same place, against the face the
   render left (skgl__point_verify's tolerance) */
static sk_result skgl__spot_verify(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                   const sk_mat4 *light_vp, int m)
{
    skgl__point_cache *c = &p->cache;
    int rect[4] = {0, 0, 0, 0};
    size_t n = (size_t)m * (size_t)m;
    skgl__verify_count v;
    float *a, *b;
    sk_result r = skgl__verify_texture(ctx, st, &c->verify_tex, &c->verify_fbo, p->desc.resolution,
                                       p->desc.resolution, "skgl_spot_render");
    if (r != SK_OK) return r;
    a = (float *)SKGL_MALLOC(n * sizeof *a);
    b = (float *)SKGL_MALLOC(n * sizeof *b);
    if (!a || !b) { SKGL_FREE(a); SKGL_FREE(b); return SK_ERR_CAPACITY; }
    memset(&v, 0, sizeof v);
    rect[2] = rect[3] = m;
    r = skgl__spot_pass(ctx, st, p, scene, light_vp, c->verify_fbo, rect, SKGL__DRAW_ALL, 1);
    p->stats.passes -= skgl__pass_callbacks(ctx);   /* not the cache's work */
    p->stats.texels -= (double)n;
    skgl__verify_read(ctx, st, p->fbo[0], 0, 0, m, m, a);
    skgl__verify_read(ctx, st, c->verify_fbo, 0, 0, m, m, b);
    skgl__verify_compare(a, b, m, m, &v);
    SKGL_FREE(a);
    SKGL_FREE(b);
    p->stats.cache_verify_texels = v.runs;
    if (r == SK_OK && v.runs > (int)(SKGL__VERIFY_RUNS * (double)n))
        r = skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_spot_render: desc.verify_cache: the spot's map (%s this frame) "
                       "differs from the uncached map in %d texels side by side, by up to %g in depth: a caster "
                       "scene.draw draws changed without skgl_point_invalidate (moving casters belong in "
                       "skgl_set_dynamic, inside its bounds); %d texels alone, float rounding, accepted",
                       c->fresh ? "drawn whole" : "kept", v.runs, (double)v.worst, v.alone);
    return r;
}
#endif /* SKGL_NO_CACHE */

/* one pass into the spot's rectangle (cleared first); nothing drawn when
   the scene lies outside the cone (fit 0) */
static sk_result skgl__spot_draw(skgl_context *ctx, skgl__st *st, skgl_point *p, const skgl_scene *scene,
                                 const sk_mat4 *light_vp, int m, int fit)
{
    static const float one = 1.0f;
    skgl_draw_info info;
    sk_result r = SK_OK;
    skgl__casters_begin(ctx, st, p->desc.slope_bias, p->desc.depth_bias, skgl__zero3);
#ifndef SKGL_NO_CACHE
    if (p->cache.tex) {
        r = skgl__spot_draw_cached(ctx, st, p, scene, light_vp, m, fit);
        if (r == SK_OK && fit == 1 && p->desc.verify_cache) r = skgl__spot_verify(ctx, st, p, scene, light_vp, m);
        skgl__model_end(ctx);
        return r;
    }
#endif
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)(p->desc.atlas ? p->desc.atlas->fbo : p->fbo[0]));
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 1);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, p->layout.face_x[0], p->layout.face_y[0], m, m);
    skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, p->layout.face_x[0], p->layout.face_y[0], m, m);
    ctx->gl.ClearBufferfv(SKGL__DEPTH, 0, &one);
    if (fit == 1) {
        memset(&info, 0, sizeof info);
        info.kind = SKGL_PASS_SPOT;
        info.light_pos = p->light_pos;
        info.light_range = p->desc.range;
        info.point = p;
        r = skgl__casters_draw(ctx, st, scene, light_vp, skgl__zero3, &info);
        p->stats.passes += skgl__pass_callbacks(ctx);
        p->stats.faces_rendered = 1;
        p->stats.texels += (double)m * m;
    } else p->stats.faces_culled = 1;
    skgl__model_end(ctx);
    return r;
}

static sk_result skgl__spot_render_body(skgl_context *ctx, skgl_point *p, const skgl_camera *cam,
                                        const skgl_scene *scene, sk_vec3 light_pos, sk_vec3 direction)
{
    skgl__st st;
    sk_mat4 vp, light_vp;
    sk_vec3 o = sk__v3(0.0f, 0.0f, 0.0f);
    int m, fit;
    sk_result r;
    const char *fn = "skgl_spot_render";
    skgl__cam ci;
    SKGL__TRY(skgl__arg_ptr(ctx, fn, p, "p"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, scene ? &scene->bounds : NULL, &ci));
    cam = &ci.gl;   /* OpenGL's convention from here on */
    SKGL__TRY(skgl__arg_scene(ctx, fn, scene, 1));
    SKGL__TRY(skgl__arg_vec(ctx, fn, light_pos, "light_pos", 0));
    SKGL__TRY(skgl__arg_vec(ctx, fn, direction, "direction", 1));
    if (!(p->desc.spot_angle > 0.0f))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: desc.spot_angle is 0: a point light renders with "
                          "skgl_point_render", fn);
    if (p->desc.atlas && !p->packed)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: a shared-atlas light needs skgl_point_atlas_pack first", fn);
    vp = sk_mat4_mul(cam->proj, cam->view);
    p->light_pos = light_pos;
    p->spot_axis = sk__normalize(direction);
    p->view = sk_frustum_from_matrix(vp);
    skgl__st_begin(ctx, &st);
    m = skgl__spot_side(ctx, &st, p, &vp);
    /* the part of the cone the view sees, snapped (a stable map), grown by
       the filter's reach: (2r) x (2r) taps, the 2x2 under each, the normal offset */
    fit = sk_spot_window(light_pos, p->spot_axis, (float)skgl__spot_radians(p), p->desc.near_plane,
                         &scene->bounds, &p->view, m,
                         (float)(p->desc.pcf_radius + 1 + (p->desc.normal_bias > 0.0f ? p->desc.normal_bias : 0.0f)),
                         p->spot_win);
    p->spot_rel = sk_spot_matrix(o, p->spot_axis, p->spot_win, p->desc.near_plane, p->desc.range);
    light_vp = sk_spot_matrix(light_pos, p->spot_axis, p->spot_win, p->desc.near_plane, p->desc.range);
    /* the filter's reach (skgl__point_reach is in units of a face's half side) */
    p->cull_margin = (float)(skgl__point_reach(p, m) * 0.5 * (p->spot_win[2] - p->spot_win[0]) * p->desc.range);
    r = skgl__point_target(ctx, &st, p, m);
    if (r != SK_OK) { skgl__st_end(ctx, &st); return r; }
    p->face_res = m;
    p->stats.passes = p->stats.faces_rendered = p->stats.faces_culled = 0;
    p->stats.casters_drawn = p->stats.casters_culled = 0;
    p->stats.texels = 0.0;
    skgl__timer_begin(ctx, &p->t_render);
    r = skgl__spot_draw(ctx, &st, p, scene, &light_vp, m, fit);
    skgl__timer_end(ctx, &p->t_render);
    p->stats.shadow_ms = p->t_render.ms;
    p->stats.resolution = m;
    p->rendered = 1;
    skgl__st_end(ctx, &st);
    return r != SK_OK ? r : skgl__check(ctx, fn);
}

SKGLDEF sk_result skgl_spot_render(skgl_context *ctx, skgl_point *p, const skgl_camera *cam, const skgl_scene *scene,
                                   sk_vec3 light_pos, sk_vec3 direction)
{
    sk_result r;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_spot_render", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_spot_render"));
    skgl__clip_depth(ctx, 0);   /* the pass under OpenGL's clip depth (CAMERA CONVENTIONS) */
    r = skgl__spot_render_body(ctx, p, cam, scene, light_pos, direction);
    skgl__clip_depth(ctx, 1);
    return skgl__said(ctx, "skgl_spot_render", r, NULL);
}

/* ---- 8. Several point lights in one atlas ------------------------------- */
// >>atlas
SKGLDEF sk_result skgl_point_atlas_create(skgl_context *ctx, int width, int height, skgl_point_atlas **out)
{
    static const char fn[] = "skgl_point_atlas_create";
    skgl__api *gl;
    skgl__st st;
    skgl__int max_size = 0;
    skgl_point_atlas *a;
    sk_result r = SK_OK;
    if (out) *out = NULL;
    SKGL__TRY(skgl__create_open(ctx, fn, 0, !out));
    if (width < 1 || height < 1)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_point_atlas_create: width x height = %d x %d: 1 or more each",
                          width, height);
    gl = &ctx->gl;
    gl->GetIntegerv(SKGL__MAX_TEXTURE_SIZE, &max_size);
    if (width > max_size)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "skgl_point_atlas_create: width = %d: at most GL_MAX_TEXTURE_SIZE %d",
                          width, max_size);
    if (height > max_size)
        return skgl__fail(ctx, SK_ERR_INVALID_ARG,
                          "skgl_point_atlas_create: height = %d: at most GL_MAX_TEXTURE_SIZE %d", height, max_size);
    a = (skgl_point_atlas *)skgl__create_alloc(ctx, fn, sizeof *a);
    if (!a) return SK_ERR_CAPACITY;
    a->w = width;
    a->h = height;
    skgl__st_begin(ctx, &st);
    gl->GenTextures(1, &a->tex); ctx->objects++;
    skgl__atlas_alloc(ctx, &st, a->tex, width, height);
    a->fbo = skgl__framebuffer(ctx, &st, 0, 0, a->tex, -1);
    skgl__st_end(ctx, &st);
    if (!a->fbo) r = skgl__fail(ctx, SK_ERR_GL, "%s: the atlas's framebuffer is not complete", fn);
    r = skgl__create_close(ctx, fn, r, "the atlas");
    if (r != SK_OK) {
        skgl_point_atlas_destroy(ctx, a);
        return r;
    }
    *out = a;
    return SK_OK;
}

SKGLDEF void skgl_point_atlas_destroy(skgl_context *ctx, skgl_point_atlas *a)
{
    if (!ctx || !a) return;
    skgl__delete_texture(ctx, &a->tex);
    skgl__delete_framebuffer(ctx, &a->fbo);
    SKGL_FREE(a);
}

SKGLDEF unsigned skgl_point_atlas_texture(const skgl_point_atlas *a) { return a ? a->tex : 0; }
SKGLDEF void skgl_point_atlas_size(const skgl_point_atlas *a, int *width, int *height)
{
    if (width) *width = a ? a->w : 0;
    if (height) *height = a ? a->h : 0;
}

/* Shelf packing of the lights' faces, all six of a light of side res[i]
   (a spot's one, nface[i] = 1):
   lights taken by side, largest first (order[] sorted so), squares placed
   left to right; a square that would pass the right edge starts a new
   shelf on top of the last one, as high as its first square, which is the
   tallest on it since sides only decrease. 1 and the corners in x, y
   (light i's face f at [6 i + f]) when everything fits in w x h, else 0. */
static int skgl__atlas_shelves(int w, int h, int n, const int *res, const int *nface, const int *order, int *x,
                               int *y)
{
    int k, f, cx = 0, sy = 0, shelf = 0;
    for (k = 0; k < n; k++) {
        int i = order[k], m = res[i];
        if (m > w) return 0;
        for (f = 0; f < nface[i]; f++) {
            if (cx + m > w) { sy += shelf; cx = 0; shelf = 0; }
            if (shelf == 0) shelf = m;
            if (sy + m > h) return 0;
            x[6 * i + f] = cx;
            y[6 * i + f] = sy;
            cx += m;
        }
    }
    return 1;
}


SKGLDEF sk_result skgl_point_atlas_pack(skgl_context *ctx, skgl_point_atlas *a, skgl_point *const *lights, int n,
                                        const skgl_camera *cam, const sk_vec3 *light_pos)
{
    skgl__st st;
    skgl__int viewport[4] = {0, 0, 0, 0};
    sk_mat4 vp;
    sk_frustum view;
    int *res, *order, *x, *y, *nface;
    int i, k, f, fits;
    sk_result r = SK_OK;
    const char *fn = "skgl_point_atlas_pack";
    skgl__cam ci;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_point_atlas_pack", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_point_atlas_pack"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, a, "a"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, lights, "lights"));
    SKGL__TRY(skgl__arg_ptr(ctx, fn, light_pos, "light_pos"));
    if (n < 1) return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: n = %d: 1 or more", fn, n);
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, NULL, &ci));
    cam = &ci.gl;   /* OpenGL's convention from here on */
    for (i = 0; i < n; i++)
        if (!lights[i] || lights[i]->desc.atlas != a || !sk__v3_finite(light_pos[i]))
            return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: lights[%d] is NULL, not in this atlas, or its light_pos "
                              "is not finite", fn, i);
    res = (int *)SKGL_MALLOC(sizeof(int) * (size_t)n * 15);
    if (!res) return skgl__fail(ctx, SK_ERR_CAPACITY, "%s: out of memory", fn);
    order = res + n;
    x = order + n;
    y = x + 6 * n;
    nface = y + 6 * n;
    skgl__st_begin(ctx, &st);
    /* each light's side, selected as skgl_point_render selects it */
    vp = sk_mat4_mul(cam->proj, cam->view);
    view = sk_frustum_from_matrix(vp);
    for (i = 0; i < n; i++) {
        skgl_point *p = lights[i];
        unsigned faces;
        p->light_pos = light_pos[i];
        p->view = view;
        if (p->desc.select_resolution && (p->desc.screen_w < 1 || p->desc.screen_h < 1) && !viewport[2])
            skgl__caller_viewport(ctx, &st, viewport);
        nface[i] = p->desc.spot_angle > 0.0f ? 1 : 6;
        res[i] = nface[i] == 1 ? skgl__spot_select(p, &vp, viewport) : skgl__point_select(p, &vp, viewport, &faces);
        if (res[i] < 1) res[i] = 1;
        lights[i]->stats.atlas_wanted = res[i];
    }
    /* pack; while it does not fit, halve the largest side */
    for (;;) {
        for (i = 0; i < n; i++) order[i] = i;
        for (i = 1; i < n; i++)   /* insertion sort by side, descending; stable */
            for (k = i; k > 0 && res[order[k - 1]] < res[order[k]]; k--) {
                int t = order[k]; order[k] = order[k - 1]; order[k - 1] = t;
            }
        fits = skgl__atlas_shelves(a->w, a->h, n, res, nface, order, x, y);
        if (fits || res[order[0]] <= 1) break;
        res[order[0]] /= 2;
    }
    if (!fits) {
        skgl__set_log(ctx, "skgl_point_atlas_pack: the faces do not fit even at one texel", NULL);
        r = SK_ERR_CAPACITY;
    }
    for (i = 0; i < n && r == SK_OK; i++) {
        sk_vsdct_layout l;
        l.face_res = res[i];
        l.atlas_w = a->w;
        l.atlas_h = a->h;
        for (f = 0; f < 6; f++) {   /* a spot's one face in every slot */
            l.face_x[f] = x[6 * i + (f < nface[i] ? f : 0)];
            l.face_y[f] = y[6 * i + (f < nface[i] ? f : 0)];
        }
        r = skgl__point_fill(ctx, &st, lights[i], &l);
        if (r == SK_OK) { lights[i]->packed = 1; lights[i]->face_res = res[i]; }
    }
    skgl__st_end(ctx, &st);
    SKGL_FREE(res);
    if (r != SK_OK) return r;
    return skgl__check(ctx, "skgl_point_atlas_pack");
}




/* ---- 9. Area lights: PCSS and PVSM (Shen et al. 2011) ------------------- */
#ifndef SKGL_NO_SOFT
// >>soft
/* 9.1 pass timing of a frame -------------------------------------------
   An area light's frame has a varying number of timed passes (PVSM: two
   per tile), so each frame takes a set of queries, set frame % ring,
   grown as needed: each timed pass the next query of the set, noted with
   its step. When a set comes round again (three frames later) it is read
   whole if its results are there (each query asked with
   GL_QUERY_RESULT_AVAILABLE first), then the set of two frames ago
   likewise; a set still busy leaves this frame untimed rather than wait.
   SKGL_TIMING_SYNC reads each pass at once (a stall per pass). */
typedef struct skgl__frame_timer {
    skgl__uint *q[SKGL__TIMER_RING];
    unsigned char *step[SKGL__TIMER_RING];
    int cap[SKGL__TIMER_RING], used[SKGL__TIMER_RING];
    unsigned frame;
    int skip;                              /* 1: this frame untimed (its set still busy) */
    int running;                           /* 1: a query of this frame's set is open */
    int out_of_memory;                     /* 1: a set could not grow this frame */
    float ms[SKGL_SOFT_STEPS];             /* per step, of the latest frame read; -1: not timed */
} skgl__frame_timer;

static void skgl__ftimer_free(skgl_context *ctx, skgl__frame_timer *t)
{
    int i;
    for (i = 0; i < SKGL__TIMER_RING; i++) {
        if (t->cap[i]) { ctx->gl.DeleteQueries(t->cap[i], t->q[i]); ctx->objects -= t->cap[i]; }
        SKGL_FREE(t->q[i]);
        SKGL_FREE(t->step[i]);
        t->q[i] = NULL;
        t->step[i] = NULL;
        t->cap[i] = t->used[i] = 0;
    }
}

static void skgl__ftimer_clear(float ms[SKGL_SOFT_STEPS])
{
    int k;
    for (k = 0; k < SKGL_SOFT_STEPS; k++) ms[k] = -1.0f;
}
static void skgl__ftimer_add(float ms[SKGL_SOFT_STEPS], int step, skgl__u64 ns)
{
    ms[step] = (ms[step] < 0.0f ? 0.0f : ms[step]) + (float)((double)ns * 1e-6);
}

/* set i read whole if every result is there (then 1; 1 too when empty) */
static int skgl__ftimer_read(skgl_context *ctx, skgl__frame_timer *t, int i)
{
    float ms[SKGL_SOFT_STEPS];
    int k;
    if (!t->used[i]) return 1;
    for (k = t->used[i] - 1; k >= 0; k--) {   /* the last first: busy, the others may be too */
        skgl__uint avail = 0;
        ctx->gl.GetQueryObjectuiv(t->q[i][k], SKGL__QUERY_RESULT_AVAILABLE, &avail);
        if (!avail) return 0;
    }
    skgl__ftimer_clear(ms);
    for (k = 0; k < t->used[i]; k++) {
        skgl__u64 ns = 0;
        ctx->gl.GetQueryObjectui64v(t->q[i][k], SKGL__QUERY_RESULT, &ns);
        skgl__ftimer_add(ms, t->step[i][k], ns);
    }
    if (!skgl__timer_disjoint(ctx)) memcpy(t->ms, ms, sizeof ms);
    t->used[i] = 0;
    return 1;
}

static void skgl__ftimer_frame(skgl_context *ctx, skgl__frame_timer *t)
{
    int slot;
    t->frame++;
    t->skip = t->out_of_memory = 0;
    if (!ctx->timing) return;
    if (ctx->timing == SKGL_TIMING_SYNC) { skgl__ftimer_clear(t->ms); return; }
    slot = (int)(t->frame % SKGL__TIMER_RING);
    t->skip = !skgl__ftimer_read(ctx, t, slot);
    (void)skgl__ftimer_read(ctx, t, (int)((t->frame + 1) % SKGL__TIMER_RING));
}

static void skgl__ftimer_begin(skgl_context *ctx, skgl__frame_timer *t, int step)
{
    int slot = (int)(t->frame % SKGL__TIMER_RING), n;
    t->running = 0;
    if (!ctx->timing || t->skip) return;
    n = t->used[slot];
    if (n == t->cap[slot]) {   /* the set grows; a failed allocation leaves the pass untimed */
        int cap = n ? 2 * n : 8;
        skgl__uint *q = (skgl__uint *)SKGL_MALLOC(sizeof *q * (size_t)cap);
        unsigned char *st = (unsigned char *)SKGL_MALLOC((size_t)cap);
        if (!q || !st) {
            SKGL_FREE(q);
            SKGL_FREE(st);
            t->out_of_memory = 1;
            return;
        }
        if (n) {
            memcpy(q, t->q[slot], sizeof *q * (size_t)n);
            memcpy(st, t->step[slot], (size_t)n);
        }
        ctx->gl.GenQueries(cap - n, q + n);
        ctx->objects += cap - n;
        SKGL_FREE(t->q[slot]);
        SKGL_FREE(t->step[slot]);
        t->q[slot] = q;
        t->step[slot] = st;
        t->cap[slot] = cap;
    }
    t->step[slot][n] = (unsigned char)step;
    ctx->gl.BeginQuery(SKGL__TIME_ELAPSED, t->q[slot][n]);
    t->running = 1;
}

static void skgl__ftimer_end(skgl_context *ctx, skgl__frame_timer *t)
{
    int slot = (int)(t->frame % SKGL__TIMER_RING), n = t->used[slot];
    if (!t->running) return;
    t->running = 0;
    if (ctx->timing == SKGL_TIMING_SYNC) {
        /* measuring mode: the pass's own time, waited for (see skgl__timer_end) */
        skgl__u64 ns = 0;
        ctx->gl.Finish();
        ctx->gl.EndQuery(SKGL__TIME_ELAPSED);
        ctx->gl.GetQueryObjectui64v(t->q[slot][n], SKGL__QUERY_RESULT, &ns);
        skgl__ftimer_add(t->ms, t->step[slot][n], ns);
        return;
    }
    ctx->gl.EndQuery(SKGL__TIME_ELAPSED);
    t->used[slot] = n + 1;
}

/* 9.2 the light ----------------------------------------------------------- */
#define SKGL__SOFT_LEVELS 14               /* the low-res map's levels: 8192 down to 1 */
#define SKGL__SOFT_FINE 4                  /* PVSM without a geometry shader: fine texels per low-res texel side */

/* PVSM's part (predicted virtual soft shadow maps, Shen et al. 2011): its passes'
   programs, their locations and the value last sent; the low-res map, the
   SMTG, the screen-sized targets; the prediction */
typedef struct skgl__pvsm {
    skgl__uint prog_cons, prog_smtg, prog_reduce, prog_filter, prog_resolve;
    skgl__int cons_u_view_proj, cons_u_model;
    skgl__int smtg_u_width, filter_u_rect, filter_u_res;
    int sent_width;                        /* -1: not sent yet */
    skgl__uint low_color, low_true, fb_low;            /* R32F MIN pyramid of the conservative
                                                          low-res map (mip levels); the plain map */
    skgl__uint fb_level[SKGL__SOFT_LEVELS];            /* level l of low_color (l >= 1) */
    int low_levels;
    /* without a geometry shader (skgl_caps.geometry_shader 0): the
       low-resolution map drawn SKGL__SOFT_FINE times finer into low_fine
       (DEPTH32F) and reduced by prog_dilate into low_color and low_true */
    skgl__uint low_fine, fb_fine, prog_dilate;
    /* where a texture cannot be sampled while one of its levels is drawn
       (skgl_caps.mip_render_level 0: ANGLE calls it a feedback loop):
       level l of the pyramid is also written to low_copy[l], a texture of
       its own, which level l + 1 reads */
    skgl__uint low_copy[SKGL__SOFT_LEVELS];
    skgl__uint smtg, fb_smtg;              /* RGBA32F, grid x (grid + 1): the SMTG, then a row of counts */
    skgl__uint screen, acc, fb_kernel, fb_acc;         /* a 3-layer array (kernel, prediction,
                                                          plane), the accumulation */
    int sw, sh;
    /* the prediction: the SMTG read back (at once or through the ring),
       its pyramid and tiles, the frustum it was made in */
    skgl__ring ring;                       /* lvp[i]: the light projection of read-back i */
    sk_mat4 ring_view[SKGL__RING];
    unsigned ring_frame[SKGL__RING];
    float *readback;                       /* grid x (grid + 1) RGBA */
    float *pyramid;                        /* laid out as sk_smtg_pyramid's */
    int pyramid_floats;
    float *grid;                           /* level 0 as given to sk_fvsm_tiles (after any halving) */
    sk_tile *tiles;
    sk_rect *rects;                        /* the tiles on this frame's base map (clip units) */
    int ntiles, tiles_cap;
    int have_prediction;
    unsigned prediction_frame;
    sk_mat4 pred_view, pred_proj;
    float lit_fraction;
} skgl__pvsm;

struct skgl_soft {
    skgl_soft_desc desc;
    /* the programs of both techniques, the mask's per-frame locations and
       the values last sent */
    skgl__uint prog_mask;                  /* PCSS: the mask; PVSM: the kernel-shape pass */
    skgl__uint prog_gbuf;
    skgl__int u_inv_view_proj, u_light_vp, u_light_pos, u_light_half, u_light_proj, u_has_normals, u_hard;
    skgl__int u_depth_map;                 /* the camera's depth convention: last sent, this frame's */
    float dmap[4], frame_dmap[4];
    skgl__int gbuf_u_view_proj, gbuf_u_model, gbuf_u_eye;
    int sent_has_normals, sent_hard;                 /* -1: not sent yet */
    int sent_common;                                 /* 1: sent holds the mask program's values */
    struct {
        sk_mat4 inv, lvp;
        float pos[3], half[2], proj[4];
    } sent;
    /* the targets, each with its framebuffer, made and checked once (the
       screen-sized ones again when the mask's size changes) */
    skgl__uint map, fb_map;                /* PCSS: the map; PVSM: the tile map (DEPTH32F, resolution^2) */
    skgl__uint gb_depth, gb_normal, fb_gbuf;           /* the G-buffer rendered here (depth_tex = 0) */
    int gw, gh;
    skgl__pvsm pvsm;                       /* SKGL_SOFT_PVSM only */
    /* this frame */
    unsigned frame;
    sk_mat4 light_view, light_proj, light_vp;
    float p00, p11, zn, zf;
    skgl__frame_timer timer;
    skgl_soft_frame_stats stats;
};

static skgl_soft_desc skgl__soft_defaults(const skgl_soft_desc *d)
{
    skgl_soft_desc r = *d;
    if (r.resolution == 0) r.resolution = r.technique == SKGL_SOFT_PVSM ? 4096 : 2048;
    if (r.lowres == 0) r.lowres = 1024;
    if (r.grid == 0) r.grid = 64;
    if (r.max_tiles == 0) r.max_tiles = 64;
    if (r.blocker_cells == 0) r.blocker_cells = 8;
    if (r.pcf_taps == 0) r.pcf_taps = 12;
    if (r.slope_bias == 0.0f) r.slope_bias = 1.5f;
    if (r.depth_bias == 0.0f) r.depth_bias = 1.0f;
    if (r.rel_bias == 0.0f) r.rel_bias = 0.002f;
    skgl__apply_switches(&r.slope_bias, &r.depth_bias, r.disable_polygon_offset, NULL, 0, NULL, 0);
    if (r.resolution_scale == 0.0f) r.resolution_scale = 1.0f;
    return r;
}

/* every rule of a skgl_soft_desc (defaults filled), in field order */
static sk_result skgl__soft_validate(skgl_context *ctx, const skgl_soft_desc *d)
{
    const char *fn = "skgl_soft_create";
    skgl__int max_size = 0;
    SKGL__RULE(d->technique == SKGL_SOFT_PCSS || d->technique == SKGL_SOFT_PVSM, fn, "technique", d->technique,
               "one of skgl_soft_technique");
    SKGL__NEED(ctx->caps.float_render || d->technique != SKGL_SOFT_PVSM, fn, "SKGL_SOFT_PVSM", SKGL__FLOAT_RENDER);
    SKGL__NEED(ctx->caps.float_blend || d->technique != SKGL_SOFT_PVSM, fn, "SKGL_SOFT_PVSM", SKGL__FLOAT_BLEND);
    ctx->gl.GetIntegerv(SKGL__MAX_TEXTURE_SIZE, &max_size);
    SKGL__RULE(d->resolution >= 16 && d->resolution <= max_size, fn, "resolution", d->resolution,
               "in 16..GL_MAX_TEXTURE_SIZE");
    SKGL__RULE(d->lowres >= 16 && d->lowres <= 8192 && skgl__is_pow2(d->lowres) && d->lowres <= max_size, fn,
               "lowres", d->lowres, "a power of two in 16..8192 (and GL_MAX_TEXTURE_SIZE)");
    SKGL__RULE(d->grid >= 4 && d->grid <= 256 && skgl__is_pow2(d->grid), fn, "grid", d->grid,
               "a power of two in 4..256");
    SKGL__RULE(d->max_tiles >= 1 && d->max_tiles <= 4096, fn, "max_tiles", d->max_tiles, "in 1..4096");
    SKGL__RULE(d->disable_conservative == 0 || d->disable_conservative == 1, fn, "disable_conservative",
               d->disable_conservative, "0 or 1");
    SKGL__RULE(d->static_scene == 0 || d->static_scene == 1, fn, "static_scene", d->static_scene, "0 or 1");
    SKGL__RULE(d->blocker_cells >= 2 && d->blocker_cells <= 16, fn, "blocker_cells", d->blocker_cells, "in 2..16");
    SKGL__RULE(d->pcf_taps >= 1 && d->pcf_taps <= 16, fn, "pcf_taps", d->pcf_taps, "in 1..16");
    SKGL__TRY(skgl__offset_rules(ctx, fn, d->slope_bias, d->depth_bias));
    SKGL__RULE(d->disable_polygon_offset == 0 || d->disable_polygon_offset == 1, fn, "disable_polygon_offset",
               d->disable_polygon_offset, "0 or 1");
    SKGL__RULE(d->rel_bias >= 0.0f && d->rel_bias <= 0.5f, fn, "rel_bias", d->rel_bias, "in [0, 0.5]");
    SKGL__RULE(d->disable_antialias == 0 || d->disable_antialias == 1, fn, "disable_antialias",
               d->disable_antialias, "0 or 1");
    SKGL__RULE(d->resolution_scale >= 0.125f && d->resolution_scale <= 8.0f, fn, "resolution_scale",
               d->resolution_scale, "in [0.125, 8]");
    SKGL__RULE(d->sync_readback == 0 || d->sync_readback == 1, fn, "sync_readback", d->sync_readback, "0 or 1");
    return SK_OK;
}

/* vertex + geometry + fragment */
static skgl__uint skgl__program_gs(skgl_context *ctx, const char *vs, const char *gs, const char *fs)
{
    skgl__uint sh[3];
    sh[0] = skgl__shader(ctx, SKGL__VERTEX_SHADER, vs, NULL);
    sh[1] = sh[0] ? skgl__shader(ctx, SKGL__GEOMETRY_SHADER, gs, NULL) : 0;
    sh[2] = sh[1] ? skgl__shader(ctx, SKGL__FRAGMENT_SHADER, fs, NULL) : 0;
    return skgl__link(ctx, sh, 3);
}

/* A framebuffer of n colour targets (level `level` of each; layered: the
   first n layers of the array texture color[0]) and a depth target (0:
   none), checked complete here, once; glDrawBuffers and
   glReadBuffer (the first colour target, or none) are its own state, set
   here too. 0 when it is not complete. */
static skgl__uint skgl__framebuffer_mrt(skgl_context *ctx, skgl__st *st, const skgl__uint *color, int n, int level,
                                        skgl__uint depth, int layered)
{
    static const skgl__enum bufs[4] = {SKGL__COLOR_ATTACHMENT0, SKGL__COLOR_ATTACHMENT1, SKGL__COLOR_ATTACHMENT2,
                                       SKGL__COLOR_ATTACHMENT0 + 3};
    skgl__api *gl = &ctx->gl;
    skgl__uint fb = 0;
    int i;
    gl->GenFramebuffers(1, &fb);
    ctx->objects++;
    skgl__st_framebuffer(ctx, st, fb);   /* glReadBuffer sets the READ framebuffer's state */
    for (i = 0; i < n; i++) {
        if (layered) gl->FramebufferTextureLayer(SKGL__DRAW_FRAMEBUFFER, bufs[i], color[0], level, i);
        else gl->FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, bufs[i], SKGL__TEXTURE_2D, color[i], level);
    }
    if (depth) gl->FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__DEPTH_ATTACHMENT, SKGL__TEXTURE_2D, depth, 0);
    if (n) {
        gl->DrawBuffers(n, bufs);
        gl->ReadBuffer(SKGL__COLOR_ATTACHMENT0);
    } else {
        skgl__draw_buffers_none(ctx);
        gl->ReadBuffer(SKGL__NONE);
    }
    if (gl->CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) != SKGL__FRAMEBUFFER_COMPLETE) {
        gl->DeleteFramebuffers(1, &fb);
        ctx->objects--;
        st->cur[SKGL__S_DRAW_FB][0] = 0;   /* GL fell back to 0 */
        st->cur[SKGL__S_READ_FB][0] = 0;
        return 0;
    }
    return fb;
}

static void skgl__delete_program(skgl_context *ctx, skgl__uint *p)
{
    if (*p) { ctx->gl.DeleteProgram(*p); ctx->objects--; *p = 0; }
}

/* the screen-sized targets (PVSM) */
static void skgl__soft_free_screen(skgl_context *ctx, skgl_soft *s)
{
    skgl__delete_texture(ctx, &s->pvsm.screen);
    skgl__delete_texture(ctx, &s->pvsm.acc);
    skgl__delete_framebuffer(ctx, &s->pvsm.fb_kernel);
    skgl__delete_framebuffer(ctx, &s->pvsm.fb_acc);
    s->pvsm.sw = s->pvsm.sh = 0;
}
static void skgl__soft_free_gbuffer(skgl_context *ctx, skgl_soft *s)
{
    skgl__delete_texture(ctx, &s->gb_depth);
    skgl__delete_texture(ctx, &s->gb_normal);
    skgl__delete_framebuffer(ctx, &s->fb_gbuf);
    s->gw = s->gh = 0;
}

/* PVSM's programs, targets, ring and arrays (a PCSS light: none) */
static void skgl__pvsm_free(skgl_context *ctx, skgl_soft *s)
{
    int i;
    skgl__delete_program(ctx, &s->pvsm.prog_cons);
    skgl__delete_program(ctx, &s->pvsm.prog_dilate);
    skgl__delete_texture(ctx, &s->pvsm.low_fine);
    skgl__delete_framebuffer(ctx, &s->pvsm.fb_fine);
    skgl__delete_program(ctx, &s->pvsm.prog_smtg);
    skgl__delete_program(ctx, &s->pvsm.prog_reduce);
    skgl__delete_program(ctx, &s->pvsm.prog_filter);
    skgl__delete_program(ctx, &s->pvsm.prog_resolve);
    skgl__delete_texture(ctx, &s->pvsm.low_color);
    skgl__delete_texture(ctx, &s->pvsm.low_true);
    skgl__delete_framebuffer(ctx, &s->pvsm.fb_low);
    for (i = 0; i < SKGL__SOFT_LEVELS; i++) skgl__delete_framebuffer(ctx, &s->pvsm.fb_level[i]);
    for (i = 0; i < SKGL__SOFT_LEVELS; i++) skgl__delete_texture(ctx, &s->pvsm.low_copy[i]);
    skgl__delete_texture(ctx, &s->pvsm.smtg);
    skgl__delete_framebuffer(ctx, &s->pvsm.fb_smtg);
    skgl__soft_free_screen(ctx, s);
    skgl__ring_free(ctx, &s->pvsm.ring);
    SKGL_FREE(s->pvsm.readback);
    SKGL_FREE(s->pvsm.pyramid);
    SKGL_FREE(s->pvsm.grid);
    SKGL_FREE(s->pvsm.tiles);
    SKGL_FREE(s->pvsm.rects);
    s->pvsm.readback = s->pvsm.pyramid = s->pvsm.grid = NULL;
    s->pvsm.tiles = NULL;
    s->pvsm.rects = NULL;
}

static void skgl__soft_free(skgl_context *ctx, skgl_soft *s)
{
    skgl__delete_program(ctx, &s->prog_mask);
    skgl__delete_program(ctx, &s->prog_gbuf);
    skgl__delete_texture(ctx, &s->map);
    skgl__delete_framebuffer(ctx, &s->fb_map);
    skgl__pvsm_free(ctx, s);
    skgl__soft_free_gbuffer(ctx, s);
    skgl__ftimer_free(ctx, &s->timer);
}

/* the fine map's side without a geometry shader (.disable_conservative:
   the low-res map's own, plain) */
static int skgl__soft_fine_factor(const skgl_context *ctx, const skgl_soft *s)
{
    int k = SKGL__SOFT_FINE;
    if (s->desc.disable_conservative) return 1;
    while (k > 1 && s->desc.lowres * k > ctx->caps.max_texture_size) k /= 2;
    return k;
}
static int skgl__soft_fine_size(const skgl_context *ctx, const skgl_soft *s)
{
    return s->desc.lowres * skgl__soft_fine_factor(ctx, s);
}

/* PVSM's passes but the kernel's (prog_mask): 1 when every one linked */
static int skgl__pvsm_programs(skgl_context *ctx, skgl_soft *s)
{
    const char *full = skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT);
    if (ctx->caps.geometry_shader)
        s->pvsm.prog_cons = skgl__program_gs(ctx, skgl__glsl(SKGL__GLSL_DEPTH_VERT),
                                             skgl__glsl(SKGL__GLSL_SOFT_CONS_GEOM),
                                             skgl__glsl(SKGL__GLSL_SOFT_CONS_FRAG));
    else
        s->pvsm.prog_dilate = skgl__program(ctx, full, skgl__glsl(SKGL__GLSL_SOFT_DILATE_FRAG), NULL);
    s->pvsm.prog_smtg = skgl__program(ctx, skgl__glsl(SKGL__GLSL_SOFT_SMTG_VERT),
                                      skgl__glsl(SKGL__GLSL_SOFT_SMTG_FRAG), NULL);
    s->pvsm.prog_reduce = skgl__program(ctx, skgl__glsl(SKGL__GLSL_SOFT_REDUCE_VERT),
                                        ctx->caps.mip_render_level ? "" : "#define SKGL_REDUCE_COPY 1\n",
                                        skgl__glsl(SKGL__GLSL_SOFT_REDUCE_FRAG));
    s->pvsm.prog_filter = skgl__program(ctx, full, skgl__glsl(SKGL__GLSL_SOFT_FILTER_FRAG), NULL);
    s->pvsm.prog_resolve = skgl__program(ctx, full, skgl__glsl(SKGL__GLSL_SOFT_RESOLVE_FRAG), NULL);
    return (s->pvsm.prog_cons || s->pvsm.prog_dilate) && s->pvsm.prog_smtg && s->pvsm.prog_reduce &&
           s->pvsm.prog_filter && s->pvsm.prog_resolve;
}

/* the programs of the technique, and of the G-buffer */
static sk_result skgl__soft_programs(skgl_context *ctx, skgl_soft *s)
{
    const char *full = skgl__glsl(SKGL__GLSL_FULLSCREEN_VERT), *common = skgl__glsl(SKGL__GLSL_SOFT_COMMON_GLSL);
    int ok = 1;
    if (s->desc.technique == SKGL_SOFT_PCSS) {
        s->prog_mask = skgl__program(ctx, full, common, skgl__glsl(SKGL__GLSL_PCSS_MASK_FRAG));
    } else {
        s->prog_mask = skgl__program(ctx, full, common, skgl__glsl(SKGL__GLSL_SOFT_KERNEL_FRAG));
        ok = skgl__pvsm_programs(ctx, s);
    }
    s->prog_gbuf = skgl__program(ctx, skgl__glsl(SKGL__GLSL_SOFT_GBUFFER_VERT), skgl__glsl(SKGL__GLSL_SOFT_GBUFFER_FRAG),
                                 NULL);
    if (!s->prog_mask || !s->prog_gbuf || !ok)
        return SK_ERR_GL;   /* the log holds the compiler's or linker's message */
    return SK_OK;
}

/* PVSM's passes but the kernel's: their constant uniforms, set once, and
   the locations of the others */
static void skgl__pvsm_constants(skgl_context *ctx, skgl__st *st, skgl_soft *s)
{
    skgl__api *gl = &ctx->gl;
    const skgl_soft_desc *d = &s->desc;
    skgl__uint p;
    float texel[2];
    if (s->pvsm.prog_cons) {
        p = s->pvsm.prog_cons;
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
        s->pvsm.cons_u_view_proj = gl->GetUniformLocation(p, "skgl_view_proj");
        s->pvsm.cons_u_model = gl->GetUniformLocation(p, "skgl_model");
        texel[0] = texel[1] = 2.0f / (float)d->lowres;
        if (gl->GetUniformLocation(p, "skgl_texel") >= 0)
            gl->Uniform2fv(gl->GetUniformLocation(p, "skgl_texel"), 1, texel);
        skgl__u1i(gl, gl->GetUniformLocation(p, "skgl_conservative"), !d->disable_conservative);
    } else {
        p = s->pvsm.prog_dilate;
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_fine"), 0);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_factor"), skgl__soft_fine_factor(ctx, s));
    }
    p = s->pvsm.prog_smtg;
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
    s->pvsm.smtg_u_width = gl->GetUniformLocation(p, "u_width");
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_screen"), 0);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_grid"), d->grid);
    p = s->pvsm.prog_reduce;
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_src"), 0);
    p = s->pvsm.prog_filter;
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
    s->pvsm.filter_u_rect = gl->GetUniformLocation(p, "u_tile_rect");
    s->pvsm.filter_u_res = gl->GetUniformLocation(p, "u_tile_res");
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_screen"), 0);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_tile"), 1);
    p = s->pvsm.prog_resolve;
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_screen"), 0);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_acc"), 1);
}

/* the uniforms that never change, set once; the locations of the others */
static void skgl__soft_constants(skgl_context *ctx, skgl__st *st, skgl_soft *s)
{
    skgl__api *gl = &ctx->gl;
    const skgl_soft_desc *d = &s->desc;
    skgl__uint p = s->prog_mask;
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)p);
    s->u_depth_map = skgl__depth_map_init(gl, p, s->dmap);
    s->u_inv_view_proj = gl->GetUniformLocation(p, "u_inv_view_proj");
    s->u_light_vp = gl->GetUniformLocation(p, "u_light_vp");
    s->u_light_pos = gl->GetUniformLocation(p, "u_light_pos");
    s->u_light_half = gl->GetUniformLocation(p, "u_light_half");
    s->u_light_proj = gl->GetUniformLocation(p, "u_light_proj");
    s->u_has_normals = gl->GetUniformLocation(p, "u_has_normals");
    s->u_hard = gl->GetUniformLocation(p, "u_hard");
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_depth"), 1);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_normals"), 2);
    skgl__u1f(gl, gl->GetUniformLocation(p, "u_rel_bias"), d->rel_bias);
    skgl__u1i(gl, gl->GetUniformLocation(p, "u_blocker_cells"), d->blocker_cells);
    if (d->technique == SKGL_SOFT_PCSS) {
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_map"), 0);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_map_cmp"), 3);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_pcf_taps"), d->pcf_taps);
    } else {
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_lowres"), 0);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_lowres_true"), 3);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_lowres_size"), d->lowres);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_lowres_levels"), s->pvsm.low_levels);
        skgl__u1i(gl, gl->GetUniformLocation(p, "u_static_scene"), d->static_scene);
        skgl__u1f(gl, gl->GetUniformLocation(p, "u_antialias"), d->disable_antialias ? 0.0f : 1.0f);
        skgl__u1f(gl, gl->GetUniformLocation(p, "u_res_scale"), d->resolution_scale);
        skgl__pvsm_constants(ctx, st, s);
    }
    s->gbuf_u_view_proj = gl->GetUniformLocation(s->prog_gbuf, "skgl_view_proj");
    s->gbuf_u_model = gl->GetUniformLocation(s->prog_gbuf, "skgl_model");
    s->gbuf_u_eye = gl->GetUniformLocation(s->prog_gbuf, "skgl_eye");
    s->sent_has_normals = s->sent_hard = s->pvsm.sent_width = -1;
}

/* levels 1.. of a texture made by skgl__color_texture (bound on unit 0's
   GL_TEXTURE_2D), sampled as a mipmap */
static void skgl__soft_levels(skgl_context *ctx, skgl__int ifmt, int w, int h, int levels, skgl__enum fmt)
{
    skgl__api *gl = &ctx->gl;
    int l;
    for (l = 1; l < levels; l++) {
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        gl->TexImage2D(SKGL__TEXTURE_2D, l, ifmt, w, h, 0, fmt, SKGL__FLOAT, NULL);
    }
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_MIN_FILTER, SKGL__NEAREST_MIPMAP_NEAREST);
    gl->TexParameteri(SKGL__TEXTURE_2D, SKGL__TEXTURE_MAX_LEVEL, levels - 1);
}

/* the framebuffer just made (bound) also draws its second output into
   level 0 of copy; 1 when still complete */
static int skgl__attach_copy(skgl_context *ctx, skgl__uint copy)
{
    static const skgl__enum bufs[2] = {SKGL__COLOR_ATTACHMENT0, SKGL__COLOR_ATTACHMENT1};
    ctx->gl.FramebufferTexture2D(SKGL__DRAW_FRAMEBUFFER, SKGL__COLOR_ATTACHMENT1, SKGL__TEXTURE_2D, copy, 0);
    ctx->gl.DrawBuffers(2, bufs);
    return ctx->gl.CheckFramebufferStatus(SKGL__DRAW_FRAMEBUFFER) == SKGL__FRAMEBUFFER_COMPLETE;
}

/* PVSM's: the low-res map, the SMTG and their framebuffers, the read-back
   ring and the CPU side of the prediction */
static sk_result skgl__pvsm_targets(skgl_context *ctx, skgl__st *st, skgl_soft *s)
{
    const skgl_soft_desc *d = &s->desc;
    const char *fn = "skgl_soft_create";
    skgl__uint low[3] = {0, 0, 0};
    int l, g = d->grid, ok;
    for (l = d->lowres, s->pvsm.low_levels = 1; l > 1; l /= 2) s->pvsm.low_levels++;
    s->pvsm.low_color = skgl__color_texture(ctx, st, SKGL__R32F, d->lowres, d->lowres, 1, SKGL__RED, SKGL__FLOAT, NULL);
    skgl__soft_levels(ctx, SKGL__R32F, d->lowres, d->lowres, s->pvsm.low_levels, SKGL__RED);
    s->pvsm.low_true = skgl__color_texture(ctx, st, SKGL__R32F, d->lowres, d->lowres, 1, SKGL__RED, SKGL__FLOAT, NULL);
    low[0] = s->pvsm.low_color;
    low[1] = s->pvsm.low_true;
    if (!ctx->caps.mip_render_level) {
        int side = d->lowres;
        for (l = 0; l + 1 < s->pvsm.low_levels; l++, side = side > 1 ? side / 2 : 1)
            s->pvsm.low_copy[l] = skgl__color_texture(ctx, st, SKGL__R32F, side, side, 1, SKGL__RED, SKGL__FLOAT, NULL);
        low[2] = s->pvsm.low_copy[0];
    }
    s->pvsm.fb_low = skgl__framebuffer_mrt(ctx, st, low, low[2] ? 3 : 2, 0, 0, 0);
    ok = s->pvsm.fb_low != 0;
    if (ok && s->pvsm.prog_dilate) {
        int fine = skgl__soft_fine_size(ctx, s);
        s->pvsm.low_fine = skgl__color_texture(ctx, st, SKGL__DEPTH_COMPONENT32F, fine, fine, 1, SKGL__DEPTH_COMPONENT,
                                          SKGL__FLOAT, NULL);
        s->pvsm.fb_fine = skgl__framebuffer_mrt(ctx, st, NULL, 0, 0, s->pvsm.low_fine, 0);
        if (!s->pvsm.fb_fine)
            return skgl__fail(ctx, SK_ERR_GL, "%s: the DEPTH32F fine low-res map's framebuffer is incomplete", fn);
    }
    for (l = 1; ok && l < s->pvsm.low_levels; l++)
        ok = (s->pvsm.fb_level[l] = skgl__framebuffer_mrt(ctx, st, &s->pvsm.low_color, 1, l, 0, 0)) != 0 &&
             (!s->pvsm.low_copy[l] || skgl__attach_copy(ctx, s->pvsm.low_copy[l]));
    if (!ok) return skgl__fail(ctx, SK_ERR_GL, "%s: R32F targets are not renderable here", fn);
    s->pvsm.smtg = skgl__color_texture(ctx, st, SKGL__RGBA32F, g, g + 1, 1, SKGL__RGBA, SKGL__FLOAT, NULL);
    s->pvsm.fb_smtg = skgl__framebuffer_mrt(ctx, st, &s->pvsm.smtg, 1, 0, 0, 0);
    if (!s->pvsm.fb_smtg) return skgl__fail(ctx, SK_ERR_GL, "%s: RGBA32F targets are not renderable here", fn);
    skgl__ring_create(ctx, st, &s->pvsm.ring, sizeof(float) * 4u * (size_t)g * (size_t)(g + 1));
    s->pvsm.readback = (float *)SKGL_MALLOC(s->pvsm.ring.bytes);
    s->pvsm.pyramid_floats = sk_smtg_pyramid_size(g, g);
    s->pvsm.pyramid = (float *)SKGL_MALLOC(sizeof(float) * (size_t)s->pvsm.pyramid_floats);
    s->pvsm.grid = (float *)SKGL_MALLOC(sizeof(float) * 2u * (size_t)g * (size_t)g);
    s->pvsm.tiles_cap = g * g;
    s->pvsm.tiles = (sk_tile *)SKGL_MALLOC(sizeof(sk_tile) * (size_t)s->pvsm.tiles_cap);
    s->pvsm.rects = (sk_rect *)SKGL_MALLOC(sizeof(sk_rect) * (size_t)s->pvsm.tiles_cap);
    if (!s->pvsm.readback || !s->pvsm.pyramid || !s->pvsm.grid || !s->pvsm.tiles || !s->pvsm.rects)
        return SK_ERR_CAPACITY;
    return SK_OK;
}

/* the map and its framebuffer; PVSM's own targets */
static sk_result skgl__soft_targets(skgl_context *ctx, skgl__st *st, skgl_soft *s)
{
    const skgl_soft_desc *d = &s->desc;
    s->map = skgl__color_texture(ctx, st, SKGL__DEPTH_COMPONENT32F, d->resolution, d->resolution, 1,
                                 SKGL__DEPTH_COMPONENT, SKGL__FLOAT, NULL);
    s->fb_map = skgl__framebuffer_mrt(ctx, st, NULL, 0, 0, s->map, 0);
    if (!s->fb_map)
        return skgl__fail(ctx, SK_ERR_GL, "skgl_soft_create: the DEPTH32F map's framebuffer is incomplete");
    return d->technique == SKGL_SOFT_PVSM ? skgl__pvsm_targets(ctx, st, s) : SK_OK;
}

SKGLDEF sk_result skgl_soft_create(skgl_context *ctx, const skgl_soft_desc *desc, skgl_soft **out)
{
    static const char fn[] = "skgl_soft_create";
    skgl_soft *s;
    skgl_soft_desc d;
    skgl__st st;
    sk_result r;
    if (out) *out = NULL;
    SKGL__TRY(skgl__create_open(ctx, fn, !desc, !out));
    d = skgl__soft_defaults(desc);
    SKGL__TRY(skgl__soft_validate(ctx, &d));
    s = (skgl_soft *)skgl__create_alloc(ctx, fn, sizeof *s);
    if (!s) return SK_ERR_CAPACITY;
    s->desc = d;
    r = skgl__soft_programs(ctx, s);
    skgl__st_begin(ctx, &st);
    if (r == SK_OK) r = skgl__soft_targets(ctx, &st, s);
    if (r == SK_OK) skgl__soft_constants(ctx, &st, s);
    skgl__st_end(ctx, &st);
    r = skgl__create_close(ctx, fn, r, "its textures and framebuffers");
    if (r != SK_OK) {
        skgl_soft_destroy(ctx, s);
        return r;
    }
    skgl__ftimer_clear(s->timer.ms);
    skgl__ftimer_clear(s->stats.step_ms);
    s->stats.shadow_ms = s->stats.mask_ms = -1.0f;
    s->stats.lit_fraction = d.technique == SKGL_SOFT_PVSM ? 1.0f : -1.0f;
    *out = s;
    return SK_OK;
}

SKGLDEF void skgl_soft_destroy(skgl_context *ctx, skgl_soft *s)
{
    if (!ctx || !s) return;
    skgl__soft_free(ctx, s);
    SKGL_FREE(s);
}
SKGLDEF skgl_soft_desc skgl_soft_get_desc(const skgl_soft *s)
{
    skgl_soft_desc d;
    if (s) return s->desc;
    memset(&d, 0, sizeof d);
    return d;
}
SKGLDEF const skgl_soft_frame_stats *skgl_soft_stats(const skgl_soft *s) { return s ? &s->stats : NULL; }
SKGLDEF sk_mat4 skgl_soft_matrix(const skgl_soft *s) { return s ? s->light_vp : sk_mat4_identity(); }
SKGLDEF int skgl_soft_tiles(const skgl_soft *s, sk_tile *out, int cap)
{
    int i;
    if (!s) return 0;
    for (i = 0; out && i < cap && i < s->pvsm.ntiles; i++) out[i] = s->pvsm.tiles[i];
    return s->pvsm.ntiles;
}
SKGLDEF int skgl_soft_tile_rects(const skgl_soft *s, sk_rect *out, int cap)
{
    int i;
    if (!s) return 0;
    for (i = 0; out && i < cap && i < s->pvsm.ntiles; i++) out[i] = s->pvsm.rects[i];
    return s->pvsm.ntiles;
}
SKGLDEF int skgl_soft_pyramid(const skgl_soft *s, float *out, int cap)
{
    int i;
    if (!s || !s->pvsm.pyramid || !s->pvsm.have_prediction) return 0;
    for (i = 0; out && i < cap && i < s->pvsm.pyramid_floats; i++) out[i] = s->pvsm.pyramid[i];
    return s->pvsm.pyramid_floats;
}

#endif /* SKGL_NO_SOFT */
/* 9.3 the light's frustum ------------------------------------------------ */
/* the light's frame as sk_mat4_look_at builds it: x = direction x up, y, -z = direction */
static int skgl__area_frame(const skgl_area_light *l, sk_vec3 *x, sk_vec3 *y, sk_vec3 *f)
{
    sk_vec3 s;
    if (!sk__v3_finite(l->direction) || !sk__v3_finite(l->up) || !(sk__len(l->direction) > 0.0f)) return 0;
    *f = sk__normalize(l->direction);
    s = sk__cross(*f, l->up);
    if (!(sk__len(s) > 1e-6f * (sk__len(l->up) > 0.0f ? sk__len(l->up) : 1.0f)))
        s = sk__cross(*f, sk__least_aligned_axis(*f));
    *x = sk__normalize(s);
    *y = sk__cross(*x, *f);
    return 1;
}

SKGLDEF void skgl_area_light_axes(const skgl_area_light *light, sk_vec3 *half_u, sk_vec3 *half_v)
{
    sk_vec3 x, y, f;
    if (!half_u || !half_v) return;
    if (!light || !skgl__area_frame(light, &x, &y, &f)) {
        *half_u = *half_v = sk__v3(0.0f, 0.0f, 0.0f);
        return;
    }
    *half_u = sk__scale(x, light->half_width);
    *half_v = sk__scale(y, light->half_height);
}

#ifndef SKGL_NO_SOFT
/* glFrustum from tangents of the light's view: x/z in [x0, x1], y/z in [y0, y1] */
static sk_mat4 skgl__tan_frustum(double x0, double x1, double y0, double y1, double zn, double zf)
{
    sk_mat4 p;
    memset(&p, 0, sizeof p);
    p.m[0] = (float)(2.0 / (x1 - x0));
    p.m[5] = (float)(2.0 / (y1 - y0));
    p.m[8] = (float)((x1 + x0) / (x1 - x0));
    p.m[9] = (float)((y1 + y0) / (y1 - y0));
    p.m[10] = (float)(-(zf + zn) / (zf - zn));
    p.m[11] = -1.0f;
    p.m[14] = (float)(-2.0 * zf * zn / (zf - zn));
    return p;
}

/* nearest distance along the light's axis of the scene bounds inside the
   frustum of those tangents (zf when none is) */
static double skgl__soft_near(const skgl_soft *s, const skgl_scene *scene, double x0, double x1, double y0,
                              double y1, double zf)
{
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    sk_frustum f = sk_frustum_from_matrix(sk_mat4_mul(skgl__tan_frustum(x0, x1, y0, y1, zf * 1e-5, zf),
                                                      s->light_view));
    double zn = zf;
    int i, n = sk_clip_frustum_aabb(&f, scene->bounds, pts, SK_CLIP_MAX_POINTS);
    for (i = 0; i < n; i++) {
        double z = -(double)sk_mat4_transform_point(s->light_view, pts[i]).z;
        if (z < zn) zn = z;
    }
    return zn;
}

/* The base frustum: from the light's centre, around the receivers the
   camera sees (the view clipped to the bounds) grown by the widest blocker
   search and kept within the bounds; its near plane at the nearest point
   of the bounds inside it, its far plane at the farthest corner. */
static sk_result skgl__soft_fit(skgl_soft *s, const skgl_camera *cam, const skgl_scene *scene,
                                const skgl_area_light *l)
{
    sk_vec3 pts[SK_CLIP_MAX_POINTS], corners[8], x, y, f;
    sk_frustum view;
    double zmax = -1e300, zn, zf, rx0 = 1e300, rx1 = -1e300, ry0 = 1e300, ry1 = -1e300;
    double bx0 = 1e300, bx1 = -1e300, by0 = 1e300, by1 = -1e300, mx, my, lim = 5.67;   /* tan 80 degrees */
    double x0, x1, y0, y1;
    int i, n;
    if (!skgl__area_frame(l, &x, &y, &f)) return SK_ERR_INVALID_ARG;
    s->light_view = sk_mat4_look_at(l->position, sk__add(l->position, f), l->up);
    for (i = 0; i < 8; i++) {
        sk_vec3 c = sk__v3(i & 1 ? scene->bounds.max.x : scene->bounds.min.x,
                           i & 2 ? scene->bounds.max.y : scene->bounds.min.y,
                           i & 4 ? scene->bounds.max.z : scene->bounds.min.z);
        corners[i] = sk_mat4_transform_point(s->light_view, c);
        if (-corners[i].z > zmax) zmax = -corners[i].z;
    }
    if (!(zmax > 0.0)) return SK_ERR_DEGENERATE;
    zf = zmax * 1.01;
    zn = zf * 1e-3;
    for (i = 0; i < 8; i++) {
        double z = -corners[i].z > zn ? -corners[i].z : zn;
        double tx = corners[i].x / z, ty = corners[i].y / z;
        if (tx < bx0) bx0 = tx;
        if (tx > bx1) bx1 = tx;
        if (ty < by0) by0 = ty;
        if (ty > by1) by1 = ty;
    }
    view = sk_frustum_from_matrix(sk_mat4_mul(cam->proj, cam->view));
    n = sk_clip_frustum_aabb(&view, scene->bounds, pts, SK_CLIP_MAX_POINTS);
    for (i = 0; i < n; i++) {
        sk_vec3 q = sk_mat4_transform_point(s->light_view, pts[i]);
        double tx, ty;
        if (!(-q.z > zn)) continue;               /* behind the light's plane: never lit by it */
        tx = q.x / -q.z; ty = q.y / -q.z;
        if (tx < rx0) rx0 = tx;
        if (tx > rx1) rx1 = tx;
        if (ty < ry0) ry0 = ty;
        if (ty > ry1) ry1 = ty;
    }
    if (!(rx1 >= rx0)) { rx0 = bx0; rx1 = bx1; ry0 = by0; ry1 = by1; }
    if (rx0 < -lim) rx0 = -lim;
    if (rx1 > lim) rx1 = lim;
    if (ry0 < -lim) ry0 = -lim;
    if (ry1 > lim) ry1 = lim;
    /* blockers of a receiver lie within half-size / distance of its ray:
       grow by that at the nearest bounds in front of the receivers, twice
       (the growth can only bring the near plane closer) */
    x0 = rx0; x1 = rx1; y0 = ry0; y1 = ry1;
    for (i = 0; i < 2; i++) {
        double z = skgl__soft_near(s, scene, x0, x1 > x0 ? x1 : x0 + 1e-6, y0, y1 > y0 ? y1 : y0 + 1e-6, zf);
        zn = z * 0.99 > zf * 1e-3 ? z * 0.99 : zf * 1e-3;
        mx = l->half_width / zn;
        my = l->half_height / zn;
        x0 = rx0 - mx > bx0 ? rx0 - mx : bx0;
        x1 = rx1 + mx < bx1 ? rx1 + mx : bx1;
        y0 = ry0 - my > by0 ? ry0 - my : by0;
        y1 = ry1 + my < by1 ? ry1 + my : by1;
        if (x0 < -lim) x0 = -lim;
        if (x1 > lim) x1 = lim;
        if (y0 < -lim) y0 = -lim;
        if (y1 > lim) y1 = lim;
    }
    if (!(x1 > x0) || !(y1 > y0)) { x0 = y0 = -1.0; x1 = y1 = 1.0; }
    /* steady under camera motion: the sides snapped outwards to multiples of
       a power of two near 1/16 of the width, the near plane down to a step
       of 2^(1/8), so the texel grid only moves when a side crosses a step */
    {
        double sx = SK_POW(2.0, SK_FLOOR(SK_LOG2((x1 - x0) / 16.0)));
        double sy = SK_POW(2.0, SK_FLOOR(SK_LOG2((y1 - y0) / 16.0)));
        x0 = SK_FLOOR(x0 / sx) * sx; x1 = SK_CEIL(x1 / sx) * sx;
        y0 = SK_FLOOR(y0 / sy) * sy; y1 = SK_CEIL(y1 / sy) * sy;
        zn = SK_POW(2.0, SK_FLOOR(SK_LOG2(zn) * 8.0) / 8.0);
    }
    s->light_proj = skgl__tan_frustum(x0, x1, y0, y1, zn, zf);
    s->light_vp = sk_mat4_mul(s->light_proj, s->light_view);
    s->p00 = s->light_proj.m[0];
    s->p11 = s->light_proj.m[5];
    s->zn = (float)zn;
    s->zf = (float)zf;
    return sk__mat_finite(&s->light_vp) ? SK_OK : SK_ERR_DEGENERATE;
}


/* a tile side rounded up to a step of 2^(1/4): under slow motion the
   predicted sizes drift, the rounded ones (and the texel grid) seldom move */
static int skgl__soft_round_res(int r, int max_res)
{
    double q = SK_POW(2.0, SK_CEIL(SK_LOG2((double)r) * 4.0 - 1e-9) / 4.0);
    int v = (int)SK_CEIL(q - 1e-9);
    return v > max_res ? max_res : v < r ? r : v;
}

/* PVSM step 6: the kd-tree's tiles; more than max_tiles: every required
   texel twice as large (half the resolution) until they fit */
static int skgl__soft_tiles(skgl_soft *s)
{
    int g = s->desc.grid, n = g * g * 2, i, k, count = 0;
    const float *top = s->pvsm.pyramid + s->pvsm.pyramid_floats - 2;
    if (!(top[0] < SK__INF) && !(top[1] < SK__INF)) return 0;      /* the SMTG is empty */
    memcpy(s->pvsm.grid, s->pvsm.pyramid, sizeof(float) * (size_t)n);
    for (k = 0; k < 24; k++) {
        count = sk_fvsm_tiles(s->pvsm.grid, g, g, s->desc.resolution, s->pvsm.tiles, s->pvsm.tiles_cap);
        if (count >= 0 && count <= s->desc.max_tiles) break;
        for (i = 0; i < n; i++) s->pvsm.grid[i] *= 2.0f;
    }
    if (count < 0) return 0;
    if (count > s->desc.max_tiles) count = s->desc.max_tiles;
    for (i = 0; i < count; i++) {
        s->pvsm.tiles[i].res_x = skgl__soft_round_res(s->pvsm.tiles[i].res_x, s->desc.resolution);
        s->pvsm.tiles[i].res_y = skgl__soft_round_res(s->pvsm.tiles[i].res_y, s->desc.resolution);
    }
    return count;
}


/* 9.4 the passes ------------------------------------------------------------
   One state-tracked call (section 3) renders everything: the G-buffer when
   none is given, the technique's passes, the mask. Each target is bound by
   its own framebuffer (no attachment changes, no status checks in a
   frame); uniforms that never change were set at create. */

/* PVSM's screen-sized targets for a w x h mask: kernel, prediction and
   plane, three layers of one array texture (one unit binds them all), in
   one framebuffer; the accumulation in another */
static sk_result skgl__soft_screen(skgl_context *ctx, skgl__st *st, skgl_soft *s, int w, int h)
{
    if (s->pvsm.sw == w && s->pvsm.sh == h) return SK_OK;
    skgl__soft_free_screen(ctx, s);
    s->pvsm.screen = skgl__color_texture(ctx, st, SKGL__RGBA32F, w, h, 3, SKGL__RGBA, SKGL__FLOAT, NULL);
    s->pvsm.acc = skgl__color_texture(ctx, st, SKGL__RGBA32F, w, h, 1, SKGL__RGBA, SKGL__FLOAT, NULL);
    s->pvsm.fb_kernel = skgl__framebuffer_mrt(ctx, st, &s->pvsm.screen, 3, 0, 0, 1);
    s->pvsm.fb_acc = skgl__framebuffer_mrt(ctx, st, &s->pvsm.acc, 1, 0, 0, 0);
    if (!s->pvsm.fb_kernel || !s->pvsm.fb_acc) {
        skgl__soft_free_screen(ctx, s);
        return skgl__fail(ctx, SK_ERR_GL, "skgl_soft_render: RGBA32F screen targets are not renderable here");
    }
    s->pvsm.sw = w;
    s->pvsm.sh = h;
    return SK_OK;
}

/* a caster pass of the light with program prog: the depth passes' state
   (its polygon offset; the low-res pass has no depth buffer, so only the
   offset's effect on gl_FragCoord.z matters there), the program, the
   identity model */
static void skgl__soft_casters(skgl_context *ctx, skgl__st *st, const skgl_soft *s, skgl__uint prog,
                               skgl__int vp_loc, skgl__int model_loc, int variant)
{
    skgl__casters_begin_with(ctx, st, prog, vp_loc, model_loc, variant, s->desc.slope_bias, s->desc.depth_bias,
                             skgl__zero3);
}

static void skgl__soft_info(skgl_draw_info *info, skgl_pass_kind kind, int index)
{
    memset(info, 0, sizeof *info);
    info->kind = kind;
    info->index = index;
}

/* step 0: the camera's depth and normals through the draw callback (depth_tex = 0) */
static sk_result skgl__soft_gbuffer(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_camera *cam,
                                    const skgl_scene *scene, int w, int h)
{
    static const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    skgl__api *gl = &ctx->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view), inv_view;
    skgl_draw_info info;
    float eye[3];
    sk_result r;
    if (s->gw != w || s->gh != h) {
        skgl__soft_free_gbuffer(ctx, s);
        s->gb_depth = skgl__color_texture(ctx, st, SKGL__DEPTH_COMPONENT32F, w, h, 1, SKGL__DEPTH_COMPONENT,
                                          SKGL__FLOAT, NULL);
        s->gb_normal = skgl__color_texture(ctx, st, SKGL__RGBA16F, w, h, 1, SKGL__RGBA, SKGL__FLOAT, NULL);
        s->fb_gbuf = skgl__framebuffer_mrt(ctx, st, &s->gb_normal, 1, 0, s->gb_depth, 0);
        if (!s->fb_gbuf) {
            skgl__soft_free_gbuffer(ctx, s);
            return skgl__fail(ctx, SK_ERR_GL, "skgl_soft_render: the G-buffer's framebuffer (DEPTH32F + RGBA16F) "
                                              "is incomplete");
        }
        s->gw = w;
        s->gh = h;
    }
    skgl__ftimer_begin(ctx, &s->timer, 0);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->fb_gbuf);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, w, h);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    skgl__st_set1(ctx, st, SKGL__S_BLEND, 0);
    skgl__st_set4(ctx, st, SKGL__S_COLOR_MASK, 1, 1, 1, 1);
    skgl__casters_begin_with(ctx, st, s->prog_gbuf, s->gbuf_u_view_proj, s->gbuf_u_model, SKGL__CV_GBUF, 0.0f, 0.0f,
                             skgl__zero3);
    gl->ClearBufferfv(SKGL__COLOR, 0, zero);
    skgl__clear_depth(ctx);
    if (!sk_mat4_inverse(cam->view, &inv_view)) inv_view = sk_mat4_identity();
    eye[0] = inv_view.m[12];
    eye[1] = inv_view.m[13];
    eye[2] = inv_view.m[14];
    if (s->gbuf_u_eye >= 0) gl->Uniform3fv(s->gbuf_u_eye, 1, eye);
    memcpy(ctx->pass_eye, eye, sizeof eye);
    skgl__soft_info(&info, SKGL_PASS_CAMERA, 0);
    r = skgl__casters_draw(ctx, st, scene, &vp, skgl__zero3, &info);
    s->stats.passes += skgl__pass_callbacks(ctx);
    skgl__ftimer_end(ctx, &s->timer);
    return r;
}

/* the uniforms of soft_common.glsl that follow the camera and the light */
static void skgl__soft_common(skgl_context *ctx, skgl_soft *s, const sk_mat4 *inv, const skgl_area_light *l,
                              unsigned normal_tex, int hard)
{
    skgl__api *gl = &ctx->gl;
    float pos[3], half[2], proj[4];
    pos[0] = l->position.x; pos[1] = l->position.y; pos[2] = l->position.z;
    half[0] = l->half_width; half[1] = l->half_height;
    proj[0] = s->p00; proj[1] = s->p11; proj[2] = s->zn; proj[3] = s->zf;
    /* each sent when it differs from the value last sent (bit for bit) */
    if (!s->sent_common || memcmp(&s->sent.inv, inv, sizeof *inv) != 0) {
        s->sent.inv = *inv;
        if (s->u_inv_view_proj >= 0) gl->UniformMatrix4fv(s->u_inv_view_proj, 1, 0, inv->m);
    }
    skgl__depth_map_send(gl, s->u_depth_map, s->dmap, s->frame_dmap);
    if (!s->sent_common || memcmp(&s->sent.lvp, &s->light_vp, sizeof s->light_vp) != 0) {
        s->sent.lvp = s->light_vp;
        if (s->u_light_vp >= 0) gl->UniformMatrix4fv(s->u_light_vp, 1, 0, s->light_vp.m);
    }
    if (!s->sent_common || memcmp(s->sent.pos, pos, sizeof pos) != 0) {
        memcpy(s->sent.pos, pos, sizeof pos);
        if (s->u_light_pos >= 0) gl->Uniform3fv(s->u_light_pos, 1, pos);
    }
    if (!s->sent_common || memcmp(s->sent.half, half, sizeof half) != 0) {
        memcpy(s->sent.half, half, sizeof half);
        if (s->u_light_half >= 0) gl->Uniform2fv(s->u_light_half, 1, half);
    }
    if (!s->sent_common || memcmp(s->sent.proj, proj, sizeof proj) != 0) {
        memcpy(s->sent.proj, proj, sizeof proj);
        if (s->u_light_proj >= 0) gl->Uniform4fv(s->u_light_proj, 1, proj);
    }
    s->sent_common = 1;
    if (s->sent_has_normals != (normal_tex != 0)) {
        s->sent_has_normals = normal_tex != 0;
        skgl__u1i(gl, s->u_has_normals, s->sent_has_normals);
    }
    if (s->sent_hard != hard) {
        s->sent_hard = hard;
        skgl__u1i(gl, s->u_hard, hard);
    }
}

/* PCSS (Fernando 2005): step 1 the map, step 7 the mask */
static sk_result skgl__soft_pcss(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_scene *scene,
                                 const skgl_area_light *l, const sk_mat4 *inv, unsigned depth_tex,
                                 unsigned normal_tex, unsigned mask_tex)
{
    skgl__unitbind b[4];
    skgl_draw_info info;
    int res = s->desc.resolution, w, h, n;
    sk_result r;
    skgl__ftimer_begin(ctx, &s->timer, 1);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->fb_map);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, res, res);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    skgl__soft_casters(ctx, st, s, ctx->depth_prog, ctx->depth_u_view_proj, ctx->depth_u_model, SKGL__CV_DEPTH);
    skgl__clear_depth(ctx);
    skgl__soft_info(&info, SKGL_PASS_AREA, 0);
    r = skgl__casters_draw(ctx, st, scene, &s->light_vp, skgl__zero3, &info);
    skgl__ftimer_end(ctx, &s->timer);
    s->stats.passes += skgl__pass_callbacks(ctx);
    s->stats.texels += (double)res * res;
    s->stats.maps = 1;
    s->stats.resolution = res;
    if (r != SK_OK) return r;
    skgl__ftimer_begin(ctx, &s->timer, 7);
    r = skgl__mask_begin(ctx, st, mask_tex, &w, &h, "skgl_soft_render");
    if (r == SK_OK) {
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->prog_mask);
        skgl__soft_common(ctx, s, inv, l, normal_tex, 0);
        n = skgl__mask_gbuffer(ctx, depth_tex, normal_tex, b);
        skgl__bind_unit(&b[n++], 0, SKGL__T_2D, s->map, ctx->point_sampler);
        skgl__bind_unit(&b[n++], 3, SKGL__T_2D, s->map, ctx->cmp_sampler);
        skgl__st_units(ctx, st, b, n);
        ctx->gl.DrawArrays(SKGL__TRIANGLES, 0, 3);
    }
    skgl__ftimer_end(ctx, &s->timer);
    return r;
}

/* PVSM step 1: the low-resolution map, conservative, into level 0 of the
   MIN pyramid (and plain into low_true): MIN blending takes the place of
   the depth test (there is no depth buffer), depth clamping keeps casters
   before the near plane. Then the pyramid's levels, one triangle each
   (soft_reduce.vert), reading level l - 1 through the non-mipmap point
   sampler while level l is drawn. */
/* PVSM step 1 without a geometry shader: the casters plain into the fine
   DEPTH32F map (depth test, no float blending), then soft_dilate.frag into
   level 0 of the pyramid and the plain map */
static sk_result skgl__soft_lowres_fine(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_scene *scene)
{
    skgl__unitbind b;
    skgl_draw_info info;
    int fine = skgl__soft_fine_size(ctx, s);
    sk_result rc;
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_fine);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, fine, fine);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    skgl__soft_casters(ctx, st, s, ctx->depth_prog, ctx->depth_u_view_proj, ctx->depth_u_model, SKGL__CV_DEPTH);
    skgl__clear_depth(ctx);
    skgl__st_set1(ctx, st, SKGL__S_DEPTH_CLAMP, 1);
    skgl__soft_info(&info, SKGL_PASS_AREA, 0);
    rc = skgl__casters_draw(ctx, st, scene, &s->light_vp, skgl__zero3, &info);
    skgl__st_set1(ctx, st, SKGL__S_DEPTH_CLAMP, 0);
    s->stats.passes += skgl__pass_callbacks(ctx);
    s->stats.texels += (double)fine * fine;
    skgl__st_screen_pass(ctx, st);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_low);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, s->desc.lowres, s->desc.lowres);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->pvsm.prog_dilate);
    skgl__bind_unit(&b, 0, SKGL__T_2D, s->pvsm.low_fine, ctx->point_sampler);
    skgl__st_units(ctx, st, &b, 1);
    ctx->gl.DrawArrays(SKGL__TRIANGLES, 0, 3);
    return rc;
}

static sk_result skgl__soft_lowres(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_scene *scene)
{
    static const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    skgl__unitbind b;
    skgl_draw_info info;
    int r = s->desc.lowres, l;
    sk_result rc;
    skgl__ftimer_begin(ctx, &s->timer, 1);
    if (s->pvsm.prog_dilate) {
        rc = skgl__soft_lowres_fine(ctx, st, s, scene);
    } else {
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_low);
        skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, r, r);
        skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
        skgl__st_set4(ctx, st, SKGL__S_COLOR_MASK, 1, 1, 1, 1);
        ctx->gl.ClearBufferfv(SKGL__COLOR, 0, one);
        ctx->gl.ClearBufferfv(SKGL__COLOR, 1, one);
        if (s->pvsm.low_copy[0]) ctx->gl.ClearBufferfv(SKGL__COLOR, 2, one);
        ctx->pass_texel[0] = ctx->pass_texel[1] = 2.0f / (float)r;
        ctx->pass_conservative = !s->desc.disable_conservative;
        skgl__soft_casters(ctx, st, s, s->pvsm.prog_cons, s->pvsm.cons_u_view_proj, s->pvsm.cons_u_model,
                           SKGL__CV_CONS);
        skgl__st_set1(ctx, st, SKGL__S_BLEND, 1);
        /* the alpha equation is the SMTG pass's: R32F targets have no alpha */
        skgl__st_set4(ctx, st, SKGL__S_BLEND_EQ, SKGL__MIN, SKGL__FUNC_ADD, 0, 0);
        skgl__st_set1(ctx, st, SKGL__S_DEPTH_CLAMP, 1);
        skgl__soft_info(&info, SKGL_PASS_AREA, 0);
        rc = skgl__casters_draw(ctx, st, scene, &s->light_vp, skgl__zero3, &info);
        skgl__st_set1(ctx, st, SKGL__S_DEPTH_CLAMP, 0);
        s->stats.passes += skgl__pass_callbacks(ctx);
        s->stats.texels += (double)r * r;
    }
    skgl__st_screen_pass(ctx, st);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, r / 2, r / 2);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->pvsm.prog_reduce);
    skgl__bind_unit(&b, 0, SKGL__T_2D, s->pvsm.low_color, ctx->point_sampler);
    skgl__st_units(ctx, st, &b, 1);
    for (l = 1; l < s->pvsm.low_levels; l++) {
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_level[l]);
        if (s->pvsm.low_copy[0]) {   /* the level below from its copy */
            skgl__bind_unit(&b, 0, SKGL__T_2D, s->pvsm.low_copy[l - 1], ctx->point_sampler);
            skgl__st_units(ctx, st, &b, 1);
        }
        ctx->gl.DrawArrays(SKGL__TRIANGLES, 3 * (l - 1), 3);
    }
    skgl__ftimer_end(ctx, &s->timer);
    return rc;
}

/* PVSM step 2: the kernel-shape buffer (inputs: the pyramid on unit 0
   through the texture's own mipmap sampling, the G-buffer on 1 and 2, the
   plain map on 3); background pixels keep the cleared state 0 */
static void skgl__soft_kernel(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_area_light *l,
                              const sk_mat4 *inv, unsigned depth_tex, unsigned normal_tex, int w, int h, int hard)
{
    static const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    skgl__unitbind b[4];
    int n;
    skgl__ftimer_begin(ctx, &s->timer, 2);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_kernel);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, w, h);
    ctx->gl.ClearBufferfv(SKGL__COLOR, 0, zero);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->prog_mask);
    skgl__soft_common(ctx, s, inv, l, normal_tex, hard);
    n = skgl__mask_gbuffer(ctx, depth_tex, normal_tex, b);
    skgl__bind_unit(&b[n++], 0, SKGL__T_2D, s->pvsm.low_color, 0);
    skgl__bind_unit(&b[n++], 3, SKGL__T_2D, s->pvsm.low_true, ctx->point_sampler);
    skgl__st_units(ctx, st, b, n);
    ctx->gl.DrawArrays(SKGL__TRIANGLES, 0, 3);
    skgl__ftimer_end(ctx, &s->timer);
}

/* PVSM step 3: the prediction into the SMTG and its row of counts, one
   point per pixel; MIN blending of the sizes, additive of the counts */
static void skgl__soft_smtg(skgl_context *ctx, skgl__st *st, skgl_soft *s, int w, int h)
{
    static const float empty[4] = {1e30f, 1e30f, 1e30f, 0.0f};
    skgl__unitbind b;
    skgl__ftimer_begin(ctx, &s->timer, 3);
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_smtg);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, s->desc.grid, s->desc.grid + 1);
    ctx->gl.ClearBufferfv(SKGL__COLOR, 0, empty);
    skgl__st_set1(ctx, st, SKGL__S_BLEND, 1);
    skgl__st_set4(ctx, st, SKGL__S_BLEND_EQ, SKGL__MIN, SKGL__FUNC_ADD, 0, 0);
    skgl__st_set4(ctx, st, SKGL__S_BLEND_FUNC, SKGL__ONE, SKGL__ONE, SKGL__ONE, SKGL__ONE);
    /* the point size from the shader (1), not the caller's glPointSize */
    skgl__st_set1(ctx, st, SKGL__S_POINT_SIZE, 1);
    skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->pvsm.prog_smtg);
    if (s->pvsm.sent_width != w) {
        s->pvsm.sent_width = w;
        skgl__u1i(&ctx->gl, s->pvsm.smtg_u_width, w);
    }
    /* texelFetch: the sampler does not matter, the kernel pass's stays */
    skgl__bind_unit(&b, 0, SKGL__T_2D_ARRAY, s->pvsm.screen, 0);
    skgl__st_units(ctx, st, &b, 1);
    ctx->gl.DrawArrays(SKGL__POINTS, 0, w * h);
    skgl__ftimer_end(ctx, &s->timer);
}

/* A read-back of the SMTG target: level 0 (+INF: no sample), its pyramid
   (sk_smtg_pyramid), the counts of the row above it; the tiles. view, proj:
   the frustum it was made in. */
static void skgl__soft_prediction(skgl_soft *s, const float *rgba, const sk_mat4 *view, const sk_mat4 *proj,
                                  unsigned frame)
{
    int g = s->desc.grid, i, c;
    double pen = 0.0, lit = 0.0;
    for (i = 0; i < g * g; i++) {
        for (c = 0; c < 2; c++) s->pvsm.grid[2 * i + c] = rgba[4 * i + c] < 1e29f ? rgba[4 * i + c] : SK__INF;
        if (rgba[4 * i + 3] > 0.0f && rgba[4 * i + 3] < 1e30f) pen += rgba[4 * i + 3];
    }
    for (i = 0; i < g; i++)
        if (rgba[4 * (g * g + i) + 3] > 0.0f && rgba[4 * (g * g + i) + 3] < 1e30f) lit += rgba[4 * (g * g + i) + 3];
    (void)sk_smtg_pyramid(s->pvsm.grid, g, g, s->pvsm.pyramid, s->pvsm.pyramid_floats);
    s->pvsm.lit_fraction = pen + lit > 0.0 ? (float)(1.0 - pen / (pen + lit)) : 1.0f;
    s->pvsm.ntiles = skgl__soft_tiles(s);
    s->pvsm.pred_view = *view;
    s->pvsm.pred_proj = *proj;
    s->pvsm.prediction_frame = frame;
    s->pvsm.have_prediction = 1;
}

/* The tiles' rectangles on this frame's base map (s->pvsm.rects, clip units),
   from the frustum the prediction was made in. The same light position
   and frame: exact, both frusta are from the light's centre with the same
   view, so a side at tangent t = (ndc + P[8]) / P[0] (x; y with P[9],
   P[5]) stays at that tangent. The light moved or turned: each tile's
   pyramid between the prediction's near and far planes (its 8 corners in
   world space) projected into this frame's frustum, and its bounding
   rectangle (the same receivers, a little more). 0 when a corner lies
   behind this frame's light plane: that prediction is of no use. */
static int skgl__soft_tile_rects(skgl_soft *s)
{
    const float *a = s->pvsm.pred_proj.m, *b = s->light_proj.m;
    float g = (float)s->desc.grid;
    int same_view = memcmp(&s->pvsm.pred_view, &s->light_view, sizeof s->light_view) == 0;
    int same_proj = memcmp(a, b, sizeof s->light_proj.m) == 0, i, k;
    sk_mat4 inv;
    if (!same_view && !sk_mat4_inverse(sk_mat4_mul(s->pvsm.pred_proj, s->pvsm.pred_view), &inv)) return 0;
    for (i = 0; i < s->pvsm.ntiles; i++) {
        const sk_tile *t = &s->pvsm.tiles[i];
        sk_rect r;
        r.x0 = -1.0f + 2.0f * (float)t->x0 / g;
        r.x1 = -1.0f + 2.0f * (float)t->x1 / g;
        r.y0 = -1.0f + 2.0f * (float)t->y0 / g;
        r.y1 = -1.0f + 2.0f * (float)t->y1 / g;
        if (same_view && !same_proj) {
            r.x0 = (float)(b[0] * (((double)r.x0 + a[8]) / a[0]) - b[8]);
            r.x1 = (float)(b[0] * (((double)r.x1 + a[8]) / a[0]) - b[8]);
            r.y0 = (float)(b[5] * (((double)r.y0 + a[9]) / a[5]) - b[9]);
            r.y1 = (float)(b[5] * (((double)r.y1 + a[9]) / a[5]) - b[9]);
        } else if (!same_view) {
            sk_rect box;
            box.x0 = box.y0 = 1e30f;
            box.x1 = box.y1 = -1e30f;
            for (k = 0; k < 8; k++) {
                sk_vec4 c, w;
                c.x = k & 1 ? r.x1 : r.x0;
                c.y = k & 2 ? r.y1 : r.y0;
                c.z = k & 4 ? 1.0f : -1.0f;
                c.w = 1.0f;
                w = sk_mat4_transform_vec4(inv, c);
                if (!(w.w != 0.0f)) return 0;
                w.x /= w.w; w.y /= w.w; w.z /= w.w; w.w = 1.0f;
                c = sk_mat4_transform_vec4(s->light_vp, w);
                if (!(c.w > 1e-6f * (s->zf > 0.0f ? s->zf : 1.0f))) return 0;   /* behind the light's plane */
                c.x /= c.w;
                c.y /= c.w;
                if (c.x < box.x0) box.x0 = c.x;
                if (c.x > box.x1) box.x1 = c.x;
                if (c.y < box.y0) box.y0 = c.y;
                if (c.y > box.y1) box.y1 = c.y;
            }
            if (!(box.x1 > box.x0) || !(box.y1 > box.y0) || !(box.x1 - box.x0 < 1e6f) || !(box.y1 - box.y0 < 1e6f))
                return 0;
            r = box;
        }
        s->pvsm.rects[i] = r;
    }
    return 1;
}

/* PVSM step 4: the prediction the tiles come from (READ-BACKS). By default
   an earlier frame's, the newest landed in the ring, its tiles carried into
   this frame's frustum, and this frame's goes into the ring; at once (a
   stall) with sync_readback, on the first render, and when a tile of the
   landed prediction reaches behind the light's plane as it is now. */
static void skgl__soft_predict(skgl_context *ctx, skgl__st *st, skgl_soft *s)
{
    int g = s->desc.grid, slot = -1, sync;
    skgl__ftimer_begin(ctx, &s->timer, 4);
    if (!s->desc.sync_readback && (slot = skgl__ring_poll(ctx, st, &s->pvsm.ring, s->pvsm.readback)) >= 0)
        skgl__soft_prediction(s, s->pvsm.readback, &s->pvsm.ring_view[slot], &s->pvsm.ring.lvp[slot],
                              s->pvsm.ring_frame[slot]);
    sync = s->desc.sync_readback || !s->pvsm.have_prediction || !skgl__soft_tile_rects(s);
    skgl__st_framebuffer(ctx, st, s->pvsm.fb_smtg);   /* glReadPixels reads the READ framebuffer */
    if (sync) {
        skgl__st_pack(ctx, st, 0, g + 1, 16 * g);
        ctx->gl.ReadPixels(0, 0, g, g + 1, SKGL__RGBA, SKGL__FLOAT, s->pvsm.readback);
        skgl__soft_prediction(s, s->pvsm.readback, &s->light_view, &s->light_proj, s->frame);
        (void)skgl__soft_tile_rects(s);   /* this frame's own frustum: the cells as they are */
    } else if ((slot = skgl__ring_slot(ctx, st, &s->pvsm.ring)) >= 0) {
        /* into a pixel pack buffer: the pointer is an offset, the call returns at once */
        skgl__st_pack(ctx, st, s->pvsm.ring.buf[slot], g + 1, 16 * g);
        ctx->gl.ReadPixels(0, 0, g, g + 1, SKGL__RGBA, SKGL__FLOAT, (void *)0);
        s->pvsm.ring.lvp[slot] = s->light_proj;
        s->pvsm.ring_view[slot] = s->light_view;
        s->pvsm.ring_frame[slot] = s->frame;
        skgl__ring_fence(ctx, &s->pvsm.ring, slot);
    }
    s->stats.readback_bytes = sync || slot >= 0 ? (int)s->pvsm.ring.bytes : 0;
    s->stats.readback_sync = sync;
    skgl__ftimer_end(ctx, &s->timer);
}

/* a draw callback may rebind textures and samplers on any unit: the
   filtering's inputs (units 0 and 1) are bound again after each */
static void skgl__st_forget_units(skgl__st *st)
{
    skgl__st_forget(st, SKGL__S_TEX(0, SKGL__T_2D_ARRAY));
    skgl__st_forget(st, SKGL__S_TEX(0, SKGL__T_SAMPLER));
    skgl__st_forget(st, SKGL__S_TEX(1, SKGL__T_2D));
    skgl__st_forget(st, SKGL__S_TEX(1, SKGL__T_SAMPLER));
}

/* PVSM steps 5 and 6, per tile: its map at its resolution into the lower-
   left of the tile map (one texel more each way: the filter's last panel
   may sample it), then the filtering of the pixels whose kernel meets it,
   added into the accumulation. The two passes share their state: the maps
   have no colour buffer (blending does not touch them), the accumulation
   no depth buffer (the depth state does not touch it). */
static sk_result skgl__soft_tile_passes(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_scene *scene,
                                        int w, int h)
{
    static const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    skgl__api *gl = &ctx->gl;
    skgl__unitbind b[2];
    skgl_draw_info info;
    int i, sx = w, sy = h;
    sk_result r = SK_OK;
    skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_acc);
    skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, w, h);
    gl->ClearBufferfv(SKGL__COLOR, 0, zero);
    skgl__st_set4(ctx, st, SKGL__S_BLEND_EQ, SKGL__FUNC_ADD, SKGL__FUNC_ADD, 0, 0);
    skgl__st_set4(ctx, st, SKGL__S_BLEND_FUNC, SKGL__ONE, SKGL__ONE, SKGL__ONE, SKGL__ONE);
    skgl__soft_casters(ctx, st, s, ctx->depth_prog, ctx->depth_u_view_proj, ctx->depth_u_model, SKGL__CV_DEPTH);
    skgl__st_set1(ctx, st, SKGL__S_BLEND, 1);
    /* one scissor box for both passes: the largest tile and a texel (a
       tile's clear then covers at least its own region), the screen (the
       filtering's full-screen pass) */
    for (i = 0; i < s->pvsm.ntiles; i++) {
        if (s->pvsm.tiles[i].res_x + 1 > sx) sx = s->pvsm.tiles[i].res_x + 1;
        if (s->pvsm.tiles[i].res_y + 1 > sy) sy = s->pvsm.tiles[i].res_y + 1;
    }
    skgl__st_set4(ctx, st, SKGL__S_SCISSOR_BOX, 0, 0, sx, sy);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 1);
    for (i = 0; i < s->pvsm.ntiles && r == SK_OK; i++) {
        const sk_tile *t = &s->pvsm.tiles[i];
        sk_rect rc = s->pvsm.rects[i];
        sk_mat4 vp = sk_mat4_mul(sk_crop_matrix(rc, -1.0f, 1.0f), s->light_vp);
        float rect[4], tres[2];
        skgl__ftimer_begin(ctx, &s->timer, 5);
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->fb_map);
        skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, t->res_x, t->res_y);
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)ctx->depth_prog);
        skgl__clear_depth(ctx);
        skgl__soft_info(&info, SKGL_PASS_AREA, 1 + i);
        r = skgl__casters_draw(ctx, st, scene, &vp, skgl__zero3, &info);
        skgl__st_forget_units(st);
        skgl__ftimer_end(ctx, &s->timer);
        s->stats.passes += skgl__pass_callbacks(ctx);
        s->stats.texels += (double)t->res_x * t->res_y;
        if (t->res_x > s->stats.resolution) s->stats.resolution = t->res_x;
        if (t->res_y > s->stats.resolution) s->stats.resolution = t->res_y;
        skgl__ftimer_begin(ctx, &s->timer, 6);
        skgl__st_set1(ctx, st, SKGL__S_DRAW_FB, (skgl__int)s->pvsm.fb_acc);
        skgl__st_set4(ctx, st, SKGL__S_VIEWPORT, 0, 0, w, h);
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->pvsm.prog_filter);
        skgl__st_set1(ctx, st, SKGL__S_VAO, (skgl__int)ctx->empty_vao);
        skgl__st_set1(ctx, st, SKGL__S_CULL_FACE, 0);
        skgl__bind_unit(&b[0], 0, SKGL__T_2D_ARRAY, s->pvsm.screen, 0);
        skgl__bind_unit(&b[1], 1, SKGL__T_2D, s->map, ctx->cmp_sampler);
        skgl__st_units(ctx, st, b, 2);
        rect[0] = rc.x0; rect[1] = rc.y0; rect[2] = rc.x1; rect[3] = rc.y1;
        tres[0] = (float)t->res_x;
        tres[1] = (float)t->res_y;
        if (s->pvsm.filter_u_rect >= 0) gl->Uniform4fv(s->pvsm.filter_u_rect, 1, rect);
        if (s->pvsm.filter_u_res >= 0) gl->Uniform2fv(s->pvsm.filter_u_res, 1, tres);
        gl->DrawArrays(SKGL__TRIANGLES, 0, 3);
        skgl__ftimer_end(ctx, &s->timer);
    }
    return r;
}

/* PVSM step 7: the mask from the kernel states and the accumulation */
static sk_result skgl__soft_resolve(skgl_context *ctx, skgl__st *st, skgl_soft *s, unsigned mask_tex)
{
    skgl__unitbind b[2];
    int w, h;
    sk_result r;
    skgl__ftimer_begin(ctx, &s->timer, 7);
    skgl__st_set1(ctx, st, SKGL__S_SCISSOR_TEST, 0);
    r = skgl__mask_begin(ctx, st, mask_tex, &w, &h, "skgl_soft_render");
    if (r == SK_OK) {
        skgl__st_set1(ctx, st, SKGL__S_PROGRAM, (skgl__int)s->pvsm.prog_resolve);
        skgl__bind_unit(&b[0], 0, SKGL__T_2D_ARRAY, s->pvsm.screen, 0);
        skgl__bind_unit(&b[1], 1, SKGL__T_2D, s->pvsm.acc, 0);
        skgl__st_units(ctx, st, b, 2);
        ctx->gl.DrawArrays(SKGL__TRIANGLES, 0, 3);
    }
    skgl__ftimer_end(ctx, &s->timer);
    return r;
}

static sk_result skgl__soft_pvsm(skgl_context *ctx, skgl__st *st, skgl_soft *s, const skgl_scene *scene,
                                 const skgl_area_light *l, const sk_mat4 *inv, unsigned depth_tex,
                                 unsigned normal_tex, unsigned mask_tex, int w, int h)
{
    int hard = !(l->half_width > 0.0f) && !(l->half_height > 0.0f);
    sk_result r = skgl__soft_screen(ctx, st, s, w, h);
    if (r == SK_OK) r = skgl__soft_lowres(ctx, st, s, scene);
    if (r != SK_OK) return r;
    skgl__soft_kernel(ctx, st, s, l, inv, depth_tex, normal_tex, w, h, hard);
    skgl__soft_smtg(ctx, st, s, w, h);
    skgl__soft_predict(ctx, st, s);
    r = skgl__soft_tile_passes(ctx, st, s, scene, w, h);
    if (r == SK_OK) r = skgl__soft_resolve(ctx, st, s, mask_tex);
    s->stats.tiles = s->pvsm.ntiles;
    s->stats.maps = s->pvsm.ntiles;
    s->stats.lit_fraction = s->pvsm.lit_fraction;
    s->stats.prediction_age = (int)(s->frame - s->pvsm.prediction_frame);
    return r;
}

/* the sum of the timed steps among `steps` (-1 ends); -1 when none was timed */
static float skgl__soft_ms(const float *ms, const int *steps)
{
    float t = -1.0f;
    for (; *steps >= 0; steps++)
        if (ms[*steps] >= 0.0f) t = (t < 0.0f ? 0.0f : t) + ms[*steps];
    return t;
}

static sk_result skgl__arg_area_light(skgl_context *ctx, const char *fn, const skgl_area_light *l)
{
    SKGL__TRY(skgl__arg_ptr(ctx, fn, l, "light"));
    SKGL__TRY(skgl__arg_vec(ctx, fn, l->position, "light->position", 0));
    SKGL__TRY(skgl__arg_vec(ctx, fn, l->direction, "light->direction", 1));
    SKGL__TRY(skgl__arg_vec(ctx, fn, l->up, "light->up", 0));
    if (!(l->half_width >= 0.0f && l->half_width < 1e30f) || !(l->half_height >= 0.0f && l->half_height < 1e30f))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: light->half_width, half_height = %g, %g: finite, 0 or more",
                          fn, (double)l->half_width, (double)l->half_height);
    return SK_OK;
}

static sk_result skgl__soft_render_body(skgl_context *ctx, skgl_soft *s, const skgl_camera *cam,
                                   const skgl_scene *scene, const skgl_area_light *light,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex)
{
    static const int shadow_steps[3] = {1, 5, -1}, mask_steps[6] = {2, 3, 4, 6, 7, -1};
    const char *fn = "skgl_soft_render", *why;
    skgl__cam ci;
    skgl__st st;
    sk_mat4 inv;
    sk_result r;
    int w = 0, h = 0;
    SKGL__TRY(skgl__arg_ptr(ctx, fn, s, "s"));
    SKGL__TRY(skgl__camera_in(ctx, fn, cam, scene ? &scene->bounds : NULL, &ci));
    SKGL__TRY(skgl__arg_scene(ctx, fn, scene, 1));
    SKGL__TRY(skgl__arg_area_light(ctx, fn, light));
    SKGL__TRY(skgl__arg_name(ctx, fn, mask_tex, "mask_tex"));
    /* the caller's depth buffer is read in its convention; shadowkit's own
       G-buffer (depth_tex 0) is drawn in OpenGL's */
    if (!sk_mat4_inverse(sk_mat4_mul(depth_tex ? cam->proj : ci.gl.proj, cam->view), &inv))
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: cam->proj * cam->view is singular", fn);
    memcpy(s->frame_dmap, depth_tex ? ci.dmap : skgl__dmap_gl, sizeof s->frame_dmap);
    cam = &ci.gl;
    r = skgl__soft_fit(s, cam, scene, light);
    if (r != SK_OK) return skgl__fail(ctx, r, "%s: the scene is wholly behind the light's plane", fn);
    skgl__st_begin(ctx, &st);
    why = skgl__texture_size(ctx, &st, mask_tex, &w, &h);
    if (why) {
        skgl__st_end(ctx, &st);
        return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: mask_tex = %u: %s", fn, mask_tex, why);
    }
    r = skgl__arg_texture(ctx, &st, fn, depth_tex, "depth_tex");
    if (r == SK_OK) r = skgl__arg_texture(ctx, &st, fn, normal_tex, "normal_tex");
    if (r != SK_OK) {
        skgl__st_end(ctx, &st);
        return r;
    }
    s->frame++;
    skgl__ftimer_frame(ctx, &s->timer);
    s->stats.passes = s->stats.maps = s->stats.resolution = 0;
    s->stats.texels = 0.0;
    s->stats.readback_bytes = s->stats.readback_sync = 0;
    if (!depth_tex) {
        r = skgl__soft_gbuffer(ctx, &st, s, cam, scene, w, h);
        depth_tex = s->gb_depth;
        normal_tex = s->gb_normal;
    }
    if (r == SK_OK)
        r = s->desc.technique == SKGL_SOFT_PVSM
                ? skgl__soft_pvsm(ctx, &st, s, scene, light, &inv, depth_tex, normal_tex, mask_tex, w, h)
                : skgl__soft_pcss(ctx, &st, s, scene, light, &inv, depth_tex, normal_tex, mask_tex);
    skgl__model_end(ctx);
    skgl__st_end(ctx, &st);
    memcpy(s->stats.step_ms, s->timer.ms, sizeof s->stats.step_ms);
    s->stats.shadow_ms = skgl__soft_ms(s->timer.ms, shadow_steps);
    s->stats.mask_ms = skgl__soft_ms(s->timer.ms, mask_steps);
    if (r != SK_OK) return r;
    if (s->timer.out_of_memory)
        return skgl__fail(ctx, SK_ERR_CAPACITY, "%s: no memory for more timer queries (the frame is drawn; some "
                                                "passes untimed)", fn);
    return skgl__check(ctx, fn);
}

SKGLDEF sk_result skgl_soft_render(skgl_context *ctx, skgl_soft *s, const skgl_camera *cam,
                                   const skgl_scene *scene, const skgl_area_light *light,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex)
{
    sk_result r;
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__enter(ctx, "skgl_soft_render", 0);
    SKGL__TRY(skgl__not_nested(ctx, "skgl_soft_render"));
    skgl__clip_depth(ctx, 0);   /* the passes under OpenGL's clip depth (CAMERA CONVENTIONS) */
    r = skgl__soft_render_body(ctx, s, cam, scene, light, depth_tex, normal_tex, mask_tex);
    skgl__clip_depth(ctx, 1);
    return skgl__said(ctx, "skgl_soft_render", r, r == SK_ERR_DEGENERATE ? "the whole scene is behind the light's "
                      "plane (the mask is not written)" : NULL);
}
#else /* SKGL_NO_SOFT: the area lights' entry points refuse, their accessors answer as for NULL */
static sk_result skgl__compiled_out(skgl_context *ctx, const char *fn, const char *macro)
{
    if (!ctx) return SK_ERR_INVALID_ARG;
    skgl__log_clear(ctx);
    return skgl__fail(ctx, SK_ERR_INVALID_ARG, "%s: compiled out (%s)", fn, macro);
}
SKGLDEF sk_result skgl_soft_create(skgl_context *ctx, const skgl_soft_desc *desc, skgl_soft **out)
{
    (void)desc;
    if (out) *out = NULL;
    return skgl__compiled_out(ctx, "skgl_soft_create", "SKGL_NO_SOFT");
}
SKGLDEF void skgl_soft_destroy(skgl_context *ctx, skgl_soft *s) { (void)ctx; (void)s; }
SKGLDEF skgl_soft_desc skgl_soft_get_desc(const skgl_soft *s)
{
    skgl_soft_desc d;
    (void)s;
    memset(&d, 0, sizeof d);
    return d;
}
SKGLDEF sk_result skgl_soft_render(skgl_context *ctx, skgl_soft *s, const skgl_camera *cam,
                                   const skgl_scene *scene, const skgl_area_light *light,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex)
{
    (void)s; (void)cam; (void)scene; (void)light; (void)depth_tex; (void)normal_tex; (void)mask_tex;
    return skgl__compiled_out(ctx, "skgl_soft_render", "SKGL_NO_SOFT");
}
SKGLDEF const skgl_soft_frame_stats *skgl_soft_stats(const skgl_soft *s) { (void)s; return NULL; }
SKGLDEF sk_mat4 skgl_soft_matrix(const skgl_soft *s) { (void)s; return sk_mat4_identity(); }
SKGLDEF int skgl_soft_tiles(const skgl_soft *s, sk_tile *out, int cap) { (void)s; (void)out; (void)cap; return 0; }
SKGLDEF int skgl_soft_tile_rects(const skgl_soft *s, sk_rect *out, int cap)
{
    (void)s; (void)out; (void)cap;
    return 0;
}
SKGLDEF int skgl_soft_pyramid(const skgl_soft *s, float *out, int cap) { (void)s; (void)out; (void)cap; return 0; }
#endif /* SKGL_NO_SOFT */


/* ---- 10. Embedded GLSL: the files of shaders_embedded/, by `make shaders` --- */
// >>glsl
/* The literals may pass C99's minimum of 4095 characters per string
   (GCC, Clang and MSVC take 64K): -Woverlength-strings is a portability
   note, silenced for this block only. */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Woverlength-strings"
#pragma GCC diagnostic ignored "-Wunused-const-variable" /* the literals of a compiled-out feature (SKGL_NO_*) */
#endif
/* SKGL_EMBEDDED_SHADERS_BEGIN */
static const char skgl__src_depth_vert[] =
    "/* Depth-only pass: shadow maps of every technique. skgl_model is set per\n"
    "   object through skgl_set_model(). A caster program (skgl_caster_create)\n"
    "   defines SKGL_CASTER and its own skgl_caster_position(); without one,\n"
    "   attribute 0 is the position. SKGL_LAYERED (layered.geom follows): the\n"
    "   world position relative to the light's origin, for every layer at once. */\n"
    "#ifndef SKGL_CASTER\n"
    "layout(location = 0) in vec3 a_position;\n"
    "vec4 skgl_caster_position() { return vec4(a_position, 1.0); }\n"
    "#endif\n"
    "uniform mat4 skgl_view_proj;\n"
    "uniform mat4 skgl_model;\n"
    "void main()\n"
    "{\n"
    "#ifdef SKGL_LAYERED\n"
    "    gl_Position = skgl_model * skgl_caster_position();   /* layered.geom applies each layer's matrix */\n"
    "#else\n"
    "    gl_Position = skgl_view_proj * (skgl_model * skgl_caster_position());\n"
    "#endif\n"
    "}\n"
    ;
static const char skgl__src_depth_frag[] =
    "/* Depth-only pass: the rasteriser writes depth; no colour output. A\n"
    "   caster program's fragment hook may discard (an alpha test). */\n"
    "void main()\n"
    "{\n"
    "#ifdef SKGL_CASTER_FRAGMENT\n"
    "    skgl_caster_fragment();\n"
    "#endif\n"
    "}\n"
    ;
static const char skgl__src_fullscreen_vert[] =
    "/* One triangle covering the viewport, from gl_VertexID alone (no buffers). */\n"
    "out vec2 v_uv;\n"
    "void main()\n"
    "{\n"
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
    "    v_uv = p;\n"
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_shadow_sample_glsl[] =
    "/* shadowkit: directional-light shadow lookup, shared by the deferred\n"
    "   shadow-mask pass and forward shaders (skgl_glsl_snippet()).\n"
    "\n"
    "   Maps are layers of one depth texture array: one layer for a standard\n"
    "   focused map, one per cascade for PSSM. A world position picks its layer by\n"
    "   view depth against the split distances (PSSM practical split scheme,\n"
    "   Romanick's VGP353 notes), optionally blending into the next cascade inside a band; or,\n"
    "   for LSPSM's partitions (Tang et al. 2017), which tile the light plane rather than\n"
    "   the view depth, the first layer whose partition rect holds it; or, for\n"
    "   RMSM (Romanick's VGP353 notes), a virtual map: the page of the point's level of detail\n"
    "   through the page table into a pool of pages (layer 0), or the nearest\n"
    "   coarser page resident. sk_shadow() takes screen derivatives (RMSM's level\n"
    "   of detail; the receiver's plane when the normal is zero): call it in\n"
    "   uniform control flow (not after a discard or an early return).\n"
    "\n"
    "   Maps may be orthographic (standard, PSSM) or perspective-warped (PSM,\n"
    "   LiSPSM): the light-clip w is divided out per pixel.\n"
    "\n"
    "   Bias (sk_bias_mode): 0, the receiver plane (the default): every texel of\n"
    "   the filter footprint is compared with the depth that the receiver's\n"
    "   tangent plane has at that texel's centre (adaptive depth bias, Dou, Yan,\n"
    "   Kerzner, Dai and Wyman 2014, Sec. 3), less a tolerance of sk_plane_bias\n"
    "   texels of the plane's own depth slope plus a few float ulps. A flat\n"
    "   receiver is then neither in its own shadow (no acne) nor moved (no\n"
    "   displacement of any shadow edge). The plane comes from the normal, or,\n"
    "   when the normal is zero, from the screen derivatives of the position\n"
    "   (receiver-plane depth bias, Isidoro 2006). 1, normal offset: the receiver\n"
    "   is pushed along its normal by sk_normal_bias texels of its layer at that\n"
    "   point (a warped map's texels change size across the view); this moves\n"
    "   every shadow edge toward the light by about sk_normal_bias texels times\n"
    "   the cotangent of the light's elevation. In both, the casters were drawn\n"
    "   with slope-scaled polygon offset (skgl_shadow_desc.slope_bias).\n"
    "   Filtering: a box of half-width R texels (per axis) over the map's texels,\n"
    "   each texel weighed by the part of the box it covers. R is\n"
    "   sk_filter_world world units in texels of the layer at the point (its\n"
    "   texels' world size, so the same penumbra in every cascade, at every\n"
    "   resolution, across a warped map), at least 1/2 (one bilinear 2x2\n"
    "   comparison) and at most SK_PCF_MAX_TEXELS; or, when sk_filter_world is\n"
    "   0, sk_pcf_radius texels (0: 1/2). Mode 1 takes the box's texels two by\n"
    "   two along each axis in hardware bilinear comparisons placed between\n"
    "   them in the ratio of their weights (Castano 2013, \"Shadow Mapping\n"
    "   Summary - Part 1\", the optimised PCF of The Witness): (ceil(2R)+1)^2\n"
    "   texels in (ceil((ceil(2R)+1)/2))^2 taps, (r+1)^2 for an integer radius\n"
    "   r, which weighs exactly what the (2r)^2 taps at p + k + 1/2 of earlier\n"
    "   versions did. Mode 0 compares each texel against its own plane depth,\n"
    "   one comparison each, with the same weights. A surface facing away from\n"
    "   the light (given a normal) is in its own shadow: 0, whatever the map says\n"
    "   near its silhouette. */\n"
    "uniform highp sampler2DArrayShadow sk_shadow_map;\n"
    "uniform mat4 sk_light_vp[8];\n"
    "uniform float sk_splits[10];       /* view depths: layer i covers [splits[i], splits[i+1]); after the\n"
    "                                      end of the last, where shadows start to fade (>= the end: no fade) */\n"
    "uniform int sk_layers;\n"
    "uniform float sk_blend_band;       /* fraction of a layer's depth range blended into the next */\n"
    "uniform int sk_bias_mode;          /* 0 receiver plane, 1 normal offset */\n"
    "uniform float sk_normal_bias;      /* texels (mode 1; mode 0 adds it if > 0) */\n"
    "uniform float sk_plane_bias;       /* mode 0: tolerance in texels of the plane's depth slope */\n"
    "/* How far (world units) the receiver position may lie from the true\n"
    "   surface: the deferred mask sets it from its depth buffer's precision\n"
    "   before calling sk_shadow(); a forward shader's interpolated positions are\n"
    "   exact (0). The receiver plane's tolerance grows by the depth this\n"
    "   distance spans in the map. */\n"
    "float sk_receiver_slack = 0.0;\n"
    "uniform int sk_pcf_radius;\n"
    "uniform float sk_filter_world;     /* the filter's half-width in world units (0: sk_pcf_radius texels) */\n"
    "uniform vec3 sk_light_dir;         /* travel direction, unit */\n"
    "uniform int sk_select_by_map;      /* 1: layer = the partition holding the point */\n"
    "uniform int sk_rmsm;               /* 1: a virtual map through sk_page_table */\n"
    "uniform highp sampler2D sk_page_table;   /* RMSM: per page of every level, (slot x, slot y)/255 and a = resident */\n"
    "uniform int sk_rmsm_pages0;        /* RMSM: pages per side at level 0 */\n"
    "uniform int sk_rmsm_levels;        /* RMSM: levels, the last one page */\n"
    "uniform int sk_rmsm_min_level;     /* RMSM: the finest level rendered; -b: the pages of request band b (rmsm_request.vert) */\n"
    "uniform int sk_rmsm_page;          /* RMSM: page side in texels (+2 border texels in the pool) */\n"
    "uniform float sk_select_extent;    /* a partition's rect in its light NDC: [-e, e]^2 */\n"
    "uniform vec2 sk_map_extent;        /* the part of each layer this frame rendered, in texture coordinates */\n"
    "\n"
    "/* World size of one texel of the layer at p: 2/res over the gradient of\n"
    "   light NDC x (and y), d(c.x/c.w)/dp = (row0 - ndc.x row3) / c.w; the larger\n"
    "   of the two sizes. For an orthographic map row3 = (0,0,0,1): constant. */\n"
    "float sk_texel_size(vec3 p, int layer)\n"
    "{\n"
    "    mat4 m = sk_light_vp[layer];\n"
    "    vec4 c = m * vec4(p, 1.0);\n"
    "    if (c.w <= 0.0) return 0.0;\n"
    "    vec3 r0 = vec3(m[0][0], m[1][0], m[2][0]), r1 = vec3(m[0][1], m[1][1], m[2][1]);\n"
    "    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);\n"
    "    float g = min(length(r0 - (c.x / c.w) * r3), length(r1 - (c.y / c.w) * r3)) / c.w;\n"
    "    return g > 0.0 ? 2.0 / (float(textureSize(sk_shadow_map, 0).x) * g) : 0.0;\n"
    "}\n"
    "\n"
    "/* the window depth that sk_receiver_slack spans in the map at p's light\n"
    "   clip c: half the length of NDC z's gradient over world position */\n"
    "float sk_slack_depth(mat4 m, vec4 c)\n"
    "{\n"
    "    vec3 jz = vec3(m[0][2], m[1][2], m[2][2]) - (c.z / c.w) * vec3(m[0][3], m[1][3], m[2][3]);\n"
    "    return 0.5 * length(jz) / c.w * sk_receiver_slack;\n"
    "}\n"
    "\n"
    "/* The receiver's tangent plane (normal n, any length; p's light clip c) as\n"
    "   a depth slope of the map: (dz/du, dz/dv) in window depth per texture\n"
    "   coordinate. With J the Jacobian of light NDC over world position at p\n"
    "   (rows j0, j1, j2; perspective maps included), the plane's points satisfy\n"
    "   n . J^-1 dndc = 0, and J^-1's columns are cross(j1, j2), cross(j2, j0),\n"
    "   cross(j0, j1) over det J. cross(j0, j1) is the map's ray through p: the\n"
    "   slope grows as tan of the angle between n and that ray, and is capped at\n"
    "   SK_PLANE_MAX_TAN (88 degrees), beyond which the surface is its own\n"
    "   silhouette. Window z and texture uv are both NDC / 2 + 1/2: the NDC ratio\n"
    "   is the window ratio. Zero for a zero normal. */\n"
    "const float SK_PLANE_MAX_TAN = 28.6;\n"
    "vec2 sk_plane_slope(mat4 m, vec4 c, vec3 n)\n"
    "{\n"
    "    vec3 ndc = c.xyz / c.w;\n"
    "    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);\n"
    "    vec3 j0 = vec3(m[0][0], m[1][0], m[2][0]) - ndc.x * r3;\n"
    "    vec3 j1 = vec3(m[0][1], m[1][1], m[2][1]) - ndc.y * r3;\n"
    "    vec3 j2 = vec3(m[0][2], m[1][2], m[2][2]) - ndc.z * r3;\n"
    "    vec3 ray = cross(j0, j1);\n"
    "    float nr = dot(n, ray), len = length(n) * length(ray);\n"
    "    if (!(abs(nr) > 1e-30 * len) || !(len > 0.0)) return vec2(0.0);\n"
    "    vec2 g = -vec2(dot(n, cross(j1, j2)), dot(n, cross(j2, j0))) / nr;\n"
    "    float cosv = abs(nr) / len;\n"
    "    float tanv = sqrt(max(1.0 - cosv * cosv, 0.0)) / cosv;\n"
    "    return tanv > SK_PLANE_MAX_TAN ? g * (SK_PLANE_MAX_TAN / tanv) : g;\n"
    "}\n"
    "\n"
    "/* the filter's half-width in texels of the layer whose light clip at p is c\n"
    "   (matrix m, texture size size), per axis of the map: sk_filter_world over\n"
    "   the world size of the layer's texels there, the length of light NDC's\n"
    "   gradient over world position (sk_texel_size) for each axis; else the\n"
    "   texel radius */\n"
    "const float SK_PCF_MAX_TEXELS = 8.0;\n"
    "vec2 sk_filter_texels(mat4 m, vec4 c, vec2 size)\n"
    "{\n"
    "    if (!(sk_filter_world > 0.0)) return vec2(max(float(sk_pcf_radius), 0.5));\n"
    "    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);\n"
    "    vec2 g = vec2(length(vec3(m[0][0], m[1][0], m[2][0]) - (c.x / c.w) * r3),\n"
    "                  length(vec3(m[0][1], m[1][1], m[2][1]) - (c.y / c.w) * r3)) / c.w;\n"
    "    return clamp(sk_filter_world * 0.5 * g * size, vec2(0.5), vec2(SK_PCF_MAX_TEXELS));\n"
    "}\n"
    "\n"
    "/* the part of texel j ([j, j + 1] in texel space) that the box [lo, hi] covers */\n"
    "float sk_box_cover(float lo, float hi, float j) { return max(min(hi, j + 1.0) - max(lo, j), 0.0); }\n"
    "\n"
    "/* Percentage-closer filtering against the receiver's plane. p: the lookup\n"
    "   in texel space of the sampled texture (texel j's centre at j + 0.5); z:\n"
    "   its window depth; gt: the plane's depth change per texel; R: the box's\n"
    "   half-width in texels. Each texel the box reaches is compared with the\n"
    "   plane's depth at its own centre, less the tolerance (plus slack, the\n"
    "   depth uncertainty of the receiver itself), and weighed by the part of\n"
    "   the box it covers. */\n"
    "float sk_pcf_plane(vec2 p, float z, vec2 gt, float slack, float layer, vec2 size, vec2 R)\n"
    "{\n"
    "    vec2 lo = p - R, hi = p + R, first = floor(lo);\n"
    "    ivec2 n = ivec2(ceil(hi) - first);\n"
    "    float tol = sk_plane_bias * (abs(gt.x) + abs(gt.y)) + slack + 4.0e-7;\n"
    "    float sum = 0.0;\n"
    "    for (int ky = 0; ky < n.y; ky++) {\n"
    "        float wy = sk_box_cover(lo.y, hi.y, first.y + float(ky));\n"
    "        for (int kx = 0; kx < n.x; kx++) {\n"
    "            float wx = sk_box_cover(lo.x, hi.x, first.x + float(kx));\n"
    "            vec2 tc = first + vec2(float(kx), float(ky)) + 0.5;\n"
    "            float zt = max(z + dot(gt, tc - p) - tol, 0.0);\n"
    "            if (wx * wy > 0.0) sum += wx * wy * texture(sk_shadow_map, vec4(tc / size, layer, zt));\n"
    "        }\n"
    "    }\n"
    "    return sum / (4.0 * R.x * R.y);\n"
    "}\n"
    "\n"
    "/* The same box through hardware 2x2 comparisons against one depth z: along\n"
    "   each axis the texels it reaches are taken in pairs (j, j + 1), each pair\n"
    "   one bilinear tap between their centres at j + 1/2 + w(j+1) / (w(j) +\n"
    "   w(j+1)) weighing w(j) + w(j+1) (a last texel alone: its centre), so the\n"
    "   tap's bilinear weights are the texels' box weights (Castano 2013) */\n"
    "float sk_pcf_taps(vec2 p, float z, float layer, vec2 size, vec2 R)\n"
    "{\n"
    "    vec2 lo = p - R, hi = p + R, first = floor(lo);\n"
    "    ivec2 taps = (ivec2(ceil(hi) - first) + 1) / 2;\n"
    "    float sum = 0.0;\n"
    "    for (int ty = 0; ty < taps.y; ty++) {\n"
    "        float y = first.y + float(2 * ty);\n"
    "        float ay = sk_box_cover(lo.y, hi.y, y), by = sk_box_cover(lo.y, hi.y, y + 1.0);\n"
    "        for (int tx = 0; tx < taps.x; tx++) {\n"
    "            float x = first.x + float(2 * tx);\n"
    "            float ax = sk_box_cover(lo.x, hi.x, x), bx = sk_box_cover(lo.x, hi.x, x + 1.0);\n"
    "            vec2 tc = vec2(x, y) + 0.5 + vec2(bx / (ax + bx), by / (ay + by));\n"
    "            sum += (ax + bx) * (ay + by) * texture(sk_shadow_map, vec4(tc / size, layer, z));\n"
    "        }\n"
    "    }\n"
    "    return sum / (4.0 * R.x * R.y);\n"
    "}\n"
    "\n"
    "#ifdef SK_SHADOW_EVSM\n"
    "/* EVSM, the filterable map (desc.filter = SKGL_FILTER_EVSM; compiled in\n"
    "   when SK_SHADOW_EVSM is defined before the snippet). Each layer has a\n"
    "   blurred moments map (Lauritzen and McCool 2008, \"Layered Variance Shadow\n"
    "   Maps\", Sec. 4): E[exp(c+ x)], E[exp(c+ x)^2], E[-exp(-c- x)],\n"
    "   E[exp(-c- x)^2] over the filter, x = 2 z - 1 the map's window depth. Each\n"
    "   warp's Chebyshev upper bound (Donnelly and Lauritzen 2006, \"Variance\n"
    "   Shadow Maps\", Eq. 5) bounds the lit fraction; the smaller of the two is\n"
    "   taken, then the light-bleeding reduction cuts the bound's tail below\n"
    "   sk_evsm.z and rescales the rest (Lauritzen 2007, GPU Gems 3 ch. 8). */\n"
    "uniform highp sampler2DArray sk_moments;   /* RGBA32F, bilinear, on `unit` + 2 */\n"
    "uniform int sk_filter;             /* 1: EVSM, 0: the PCF of sk_shadow_layer */\n"
    "uniform vec4 sk_evsm;              /* x c+, y c-, z light-bleeding reduction, w the smallest variance,\n"
    "                                      in window depth (each warp's scaled by its slope) */\n"
    "\n"
    "float sk_chebyshev(vec2 m, float t, float min_var, float bleed)\n"
    "{\n"
    "    if (t <= m.x) return 1.0;\n"
    "    float var = max(m.y - m.x * m.x, min_var);\n"
    "    float d = t - m.x;\n"
    "    float p = var / (var + d * d);\n"
    "    return clamp((p - bleed) / (1.0 - bleed), 0.0, 1.0);\n"
    "}\n"
    "\n"
    "/* uv: the lookup in the layer; z: the receiver's window depth */\n"
    "float sk_evsm_visibility(vec2 uv, float z, float layer)\n"
    "{\n"
    "    vec4 m = textureLod(sk_moments, vec3(uv, layer), 0.0);\n"
    "    float x = 2.0 * z - 1.0;\n"
    "    vec2 w = vec2(exp(sk_evsm.x * x), -exp(-sk_evsm.y * x));\n"
    "    /* the variance a depth spread of sk_evsm.w makes in each warp: its slope times the spread */\n"
    "    vec2 s = 2.0 * sk_evsm.w * sk_evsm.xy * abs(w);\n"
    "    return min(sk_chebyshev(m.xy, w.x, s.x * s.x, sk_evsm.z), sk_chebyshev(m.zw, w.y, s.y * s.y, sk_evsm.z));\n"
    "}\n"
    "#endif\n"
    "\n"
    "float sk_shadow_layer(vec3 world_pos, vec3 world_normal, vec3 plane_normal, int layer)\n"
    "{\n"
    "    float nb = sk_bias_mode == 1 || sk_normal_bias > 0.0 ? sk_normal_bias : 0.0;\n"
    "    vec3 p = nb > 0.0 ? world_pos + world_normal * (nb * sk_texel_size(world_pos, layer)) : world_pos;\n"
    "    vec4 c = sk_light_vp[layer] * vec4(p, 1.0);\n"
    "    if (c.w <= 0.0) return 1.0;\n"
    "    vec3 ndc = c.xyz / c.w;\n"
    "    vec3 uvz = ndc * 0.5 + 0.5;\n"
    "    if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, sk_map_extent))) return 1.0;\n"
    "    if (uvz.z > 1.0) return 1.0;\n"
    "    float z = max(uvz.z, 0.0);\n"
    "#ifdef SK_SHADOW_EVSM\n"
    "    if (sk_filter == 1) return sk_evsm_visibility(uvz.xy, z, float(layer));\n"
    "#endif\n"
    "    vec2 size = vec2(textureSize(sk_shadow_map, 0).xy);\n"
    "    vec2 R = sk_filter_texels(sk_light_vp[layer], c, size);\n"
    "    if (sk_bias_mode == 0) {\n"
    "        vec2 g = sk_plane_slope(sk_light_vp[layer], c, plane_normal);\n"
    "        return sk_pcf_plane(uvz.xy * size, z, g / size, sk_slack_depth(sk_light_vp[layer], c), float(layer), size,\n"
    "                            R);\n"
    "    }\n"
    "    if (R.x <= 0.5 && R.y <= 0.5)\n"
    "        return texture(sk_shadow_map, vec4(uvz.xy, float(layer), z));\n"
    "    return sk_pcf_taps(uvz.xy * size, z, float(layer), size, R);\n"
    "}\n"
    "\n"
    "/* RMSM: the point through the page table, from its level up to the\n"
    "   coarsest; each pool page has a border of one texel, which bounds the\n"
    "   normal offset's reach and the filter to a 2x2 comparison */\n"
    "float sk_shadow_rmsm(vec3 world_pos, vec3 world_normal, vec3 plane_normal, float lod)\n"
    "{\n"
    "    vec4 c0 = sk_light_vp[0] * vec4(world_pos, 1.0);\n"
    "    vec2 st = c0.xy / c0.w * 0.5 + 0.5;\n"
    "    if (any(lessThan(st, vec2(0.0))) || any(greaterThanEqual(st, vec2(1.0)))) return 1.0;\n"
    "    float vres = float(sk_rmsm_pages0 * sk_rmsm_page), page = float(sk_rmsm_page);\n"
    "    vec2 pool = vec2(textureSize(sk_shadow_map, 0).xy);\n"
    "    int band = max(-sk_rmsm_min_level, 0);\n"
    "    int first = int(floor(lod)) - band;\n"
    "    for (int level = clamp(first, max(sk_rmsm_min_level, 0), sk_rmsm_levels - 1); level < sk_rmsm_levels; level++) {\n"
    "        int n = sk_rmsm_pages0 >> level;\n"
    "        ivec2 pg = min(ivec2(st * float(n)), ivec2(n - 1));\n"
    "        vec4 e = texelFetch(sk_page_table, ivec2(2 * sk_rmsm_pages0 - 2 * n + pg.x, pg.y), 0);\n"
    "        if (e.a < 0.5) continue;\n"
    "        /* texels of this level: the map at vres / 2^level */\n"
    "        float lres = vres / exp2(float(level));\n"
    "        float texel = sk_texel_size(world_pos, 0) * (pool.x / lres);\n"
    "        float nb = sk_bias_mode == 1 || sk_normal_bias > 0.0 ? min(sk_normal_bias, 0.9) : 0.0;\n"
    "        vec4 c = sk_light_vp[0] * vec4(world_pos + world_normal * (nb * texel), 1.0);\n"
    "        vec3 uvz = c.xyz / c.w * 0.5 + 0.5;\n"
    "        if (uvz.z > 1.0) return 1.0;\n"
    "        vec2 f = clamp(uvz.xy * lres - vec2(pg) * page, vec2(-0.5), vec2(page + 0.5));\n"
    "        vec2 slot = floor(e.rg * 255.0 + 0.5);\n"
    "        vec2 pp = slot * (page + 2.0) + 1.0 + f;\n"
    "        if (sk_bias_mode == 0)\n"
    "            return sk_pcf_plane(pp, max(uvz.z, 0.0), sk_plane_slope(sk_light_vp[0], c, plane_normal) / lres,\n"
    "                                sk_slack_depth(sk_light_vp[0], c), 0.0, pool, vec2(0.5));\n"
    "        return texture(sk_shadow_map, vec4(pp / pool, 0.0, max(uvz.z, 0.0)));\n"
    "    }\n"
    "    return 1.0;\n"
    "}\n"
    "\n"
    "/* the distance fade: v toward lit over [start, end) of the view depth,\n"
    "   start stored after the last split (none when it is not before the end) */\n"
    "float sk_fade(float v, float view_depth, float end)\n"
    "{\n"
    "    float start = sk_splits[sk_layers + 1];\n"
    "    if (!(start < end)) return v;\n"
    "    return mix(v, 1.0, clamp((view_depth - start) / (end - start), 0.0, 1.0));\n"
    "}\n"
    "\n"
    "float sk_shadow_map_visibility(vec3 world_pos, vec3 world_normal, float view_depth)\n"
    "{\n"
    "    float rmsm_lod = 0.0;\n"
    "    if (sk_rmsm != 0) {\n"
    "        /* the level of detail as rmsm_analyze.frag takes it, before any branch */\n"
    "        vec4 c = sk_light_vp[0] * vec4(world_pos, 1.0);\n"
    "        float vres = float(sk_rmsm_pages0 * sk_rmsm_page);\n"
    "        vec2 st = c.xy / c.w * 0.5 + 0.5;\n"
    "        vec2 dx = dFdx(st) * vres, dy = dFdy(st) * vres;\n"
    "        float tr = dot(dx, dx) + dot(dy, dy), det = abs(dx.x * dy.y - dx.y * dy.x);\n"
    "        rmsm_lod = log2(max(det / max(sqrt(0.5 * (tr + sqrt(max(tr * tr - 4.0 * det * det, 0.0)))), 1e-30), 1e-30));\n"
    "    }\n"
    "    /* the receiver's plane: its normal, else the screen derivatives of the\n"
    "       position (taken here, before any branch) */\n"
    "    vec3 pn = cross(dFdx(world_pos), dFdy(world_pos));\n"
    "    if (dot(world_normal, world_normal) > 0.0) pn = world_normal;\n"
    "    if (dot(world_normal, sk_light_dir) >= 0.0 && dot(world_normal, world_normal) > 0.0) return 0.0;\n"
    "    if (sk_rmsm != 0) return sk_shadow_rmsm(world_pos, world_normal, pn, rmsm_lod);\n"
    "    if (sk_select_by_map != 0) {\n"
    "        if (view_depth < sk_splits[0] || view_depth >= sk_splits[1]) return 1.0;\n"
    "        for (int i = 0; i < sk_layers; i++) {\n"
    "            vec4 c = sk_light_vp[i] * vec4(world_pos, 1.0);\n"
    "            if (all(lessThanEqual(abs(c.xy), vec2(sk_select_extent * c.w))))\n"
    "                return sk_fade(sk_shadow_layer(world_pos, world_normal, pn, i), view_depth, sk_splits[1]);\n"
    "        }\n"
    "        return 1.0;\n"
    "    }\n"
    "    if (view_depth < sk_splits[0] || view_depth >= sk_splits[sk_layers]) return 1.0;\n"
    "    int layer = 0;\n"
    "    for (int i = 1; i < sk_layers; i++)\n"
    "        if (view_depth >= sk_splits[i]) layer = i;\n"
    "    float v = sk_shadow_layer(world_pos, world_normal, pn, layer);\n"
    "    if (sk_blend_band > 0.0 && layer + 1 < sk_layers) {\n"
    "        float end = sk_splits[layer + 1];\n"
    "        float band = sk_blend_band * (end - sk_splits[layer]);\n"
    "        float t = (view_depth - (end - band)) / band;\n"
    "        if (t > 0.0)\n"
    "            v = mix(v, sk_shadow_layer(world_pos, world_normal, pn, layer + 1), t);\n"
    "    }\n"
    "    return sk_fade(v, view_depth, sk_splits[sk_layers]);\n"
    "}\n"
    "\n"
    "/* Contact shadows in a forward shader (skgl_shadow_desc.contact_length):\n"
    "   \"#define SK_SHADOW_CONTACT 1\" before the snippet declares the camera's\n"
    "   depth buffer and the march's uniforms; skgl_shadow_bind binds the buffer\n"
    "   named by skgl_shadow_contact_depth on unit + 3 and sets them, when the\n"
    "   light has contact_length > 0 (without the define, or with length 0, the\n"
    "   snippet is as it was: no sampler, no call). The march is the mask's\n"
    "   (shadow_mask.frag, McGuire and Mara 2014's depth-buffer ray casting with\n"
    "   a constant thickness) from the receiver's own position and normal; the\n"
    "   buffer's surface normals, which a forward pass has no buffer of, come\n"
    "   from the depth buffer itself (sk_contact_normal). */\n"
    "#ifndef SK_SHADOW_CONTACT\n"
    "#define SK_SHADOW_CONTACT 0\n"
    "#endif\n"
    "#if SK_SHADOW_CONTACT\n"
    "uniform highp sampler2D sk_contact_depth;  /* the camera's depth buffer: a depth pre-pass, not the target drawn */\n"
    "uniform vec4 sk_contact;                   /* x the march's length (world units; 0: off), y steps, z thickness */\n"
    "uniform mat4 sk_contact_camera[3];         /* the camera of sk_shadow's positions: view-projection, its\n"
    "                                              inverse, view */\n"
    "uniform vec4 sk_contact_depth_map;         /* the buffer's depth convention: NDC z = depth * x + y */\n"
    "\n"
    "vec3 sk_contact_world(ivec2 q)\n"
    "{\n"
    "    vec2 ndc_xy = (vec2(q) + 0.5) / vec2(textureSize(sk_contact_depth, 0)) * 2.0 - 1.0;\n"
    "    float d = texelFetch(sk_contact_depth, q, 0).r;\n"
    "    vec4 w = sk_contact_camera[1] * vec4(ndc_xy, d * sk_contact_depth_map.x + sk_contact_depth_map.y, 1.0);\n"
    "    return w.xyz / w.w;\n"
    "}\n"
    "\n"
    "float sk_contact_view_depth(vec3 p) { return -(sk_contact_camera[2] * vec4(p, 1.0)).z; }\n"
    "\n"
    "/* the buffer surface's normal at pixel q (position b), toward the camera:\n"
    "   on each axis the one-sided difference toward the side that continues\n"
    "   q's plane, the one whose next two pixels extrapolate q's view depth best\n"
    "   (the second difference; at a crease, such as a wall's foot on the\n"
    "   ground, the other side bends away) */\n"
    "vec3 sk_contact_normal(ivec2 q, vec3 b)\n"
    "{\n"
    "    ivec2 last = textureSize(sk_contact_depth, 0) - 1;\n"
    "    vec3 t[2];\n"
    "    float zb = sk_contact_view_depth(b);\n"
    "    for (int a = 0; a < 2; a++) {\n"
    "        ivec2 e = ivec2(1 - a, a);\n"
    "        vec3 lo = sk_contact_world(clamp(q - e, ivec2(0), last)), hi = sk_contact_world(clamp(q + e, ivec2(0), last));\n"
    "        float zl2 = sk_contact_view_depth(sk_contact_world(clamp(q - 2 * e, ivec2(0), last)));\n"
    "        float zh2 = sk_contact_view_depth(sk_contact_world(clamp(q + 2 * e, ivec2(0), last)));\n"
    "        float el = abs(2.0 * sk_contact_view_depth(lo) - zl2 - zb), eh = abs(2.0 * sk_contact_view_depth(hi) - zh2 - zb);\n"
    "        t[a] = eh < el ? hi - b : b - lo;\n"
    "    }\n"
    "    vec3 n = cross(t[0], t[1]);\n"
    "    vec3 to_eye = -(sk_contact_camera[2] * vec4(b, 1.0)).xyz * mat3(sk_contact_camera[2]);\n"
    "    return normalize(dot(n, to_eye) < 0.0 ? -n : n);\n"
    "}\n"
    "\n"
    "/* the buffer's view-depth step at pixel q (depth z): the largest one-sided\n"
    "   difference to its four neighbours, as shadow_mask.frag's\n"
    "   receiver_depth_step */\n"
    "float sk_contact_step(ivec2 q, float z)\n"
    "{\n"
    "    ivec2 last = textureSize(sk_contact_depth, 0) - 1;\n"
    "    float g = 0.0;\n"
    "    for (int a = 0; a < 2; a++) {\n"
    "        ivec2 e = ivec2(1 - a, a);\n"
    "        ivec2 lo = clamp(q - e, ivec2(0), last), hi = clamp(q + e, ivec2(0), last);\n"
    "        float dl = abs(sk_contact_view_depth(sk_contact_world(lo)) - z);\n"
    "        float dh = abs(sk_contact_view_depth(sk_contact_world(hi)) - z);\n"
    "        g = max(g, max(lo == q ? 0.0 : dl, hi == q ? 0.0 : dh));\n"
    "    }\n"
    "    return g;\n"
    "}\n"
    "\n"
    "/* 0 blocked, 1 clear: shadow_mask.frag's contact_visibility, the receiver's\n"
    "   normal its own, the buffer's from its depth (a receiver without a\n"
    "   normal: the buffer must lie in front by more than two of the receiver's\n"
    "   pixel depth steps) */\n"
    "float sk_contact_visibility(vec3 world, vec3 n, float z)\n"
    "{\n"
    "    vec2 size = vec2(textureSize(sk_contact_depth, 0));\n"
    "    bool plane = dot(n, n) > 0.0;\n"
    "    float plane_tol = 1e-3 * z, tol = 0.0;\n"
    "    int steps = int(sk_contact.y);\n"
    "    if (!plane) {\n"
    "        vec4 c0 = sk_contact_camera[0] * vec4(world, 1.0);\n"
    "        ivec2 q0 = clamp(ivec2((c0.xy / c0.w * 0.5 + 0.5) * size), ivec2(0), ivec2(size) - 1);\n"
    "        tol = 2.0 * sk_contact_step(q0, z);\n"
    "    }\n"
    "    for (int i = 1; i <= steps; i++) {\n"
    "        vec3 p = world - sk_light_dir * (sk_contact.x * float(i) / float(steps));\n"
    "        vec4 c = sk_contact_camera[0] * vec4(p, 1.0);\n"
    "        if (c.w <= 0.0) break;\n"
    "        vec2 win = (c.xy / c.w * 0.5 + 0.5) * size;\n"
    "        if (any(lessThan(win, vec2(0.0))) || any(greaterThanEqual(win, size))) break;\n"
    "        ivec2 q = ivec2(win);\n"
    "        vec3 b = sk_contact_world(q);\n"
    "        float in_front = sk_contact_view_depth(p) - sk_contact_view_depth(b);\n"
    "        if (in_front <= tol || in_front >= sk_contact.z) continue;\n"
    "        if (!plane) return 0.0;\n"
    "        if (dot(b - world, normalize(n)) > plane_tol && dot(b - p, sk_contact_normal(q, b)) >= 0.0) return 0.0;\n"
    "    }\n"
    "    return 1.0;\n"
    "}\n"
    "#endif\n"
    "\n"
    "/* the map's visibility v combined with the contact march (when on) */\n"
    "float sk_contact_combine(float v, vec3 world_pos, vec3 world_normal, float view_depth)\n"
    "{\n"
    "#if SK_SHADOW_CONTACT\n"
    "    if (sk_contact.x > 0.0 && v > 0.0) v = min(v, sk_contact_visibility(world_pos, world_normal, view_depth));\n"
    "#endif\n"
    "    return v;\n"
    "}\n"
    "\n"
    "/* the shadow at world_pos: the map's visibility (sk_shadow_map_visibility),\n"
    "   with contact shadows when SK_SHADOW_CONTACT is on */\n"
    "float sk_shadow(vec3 world_pos, vec3 world_normal, float view_depth)\n"
    "{\n"
    "    return sk_contact_combine(sk_shadow_map_visibility(world_pos, world_normal, view_depth), world_pos, world_normal,\n"
    "                              view_depth);\n"
    "}\n"
    ;
static const char skgl__src_shadow_mask_frag[] =
    "/* Deferred shadow mask: camera depth (and optional world normals) in,\n"
    "   visibility out (1 lit, 0 shadowed), one value per pixel in an R16F target.\n"
    "   World positions are reconstructed from window depth exactly as the\n"
    "   reference does: NDC from the pixel centre and 2*depth - 1 (the\n"
    "   camera's convention: u_depth_map), inverse view-projection, w-divide. */\n"
    "in vec2 v_uv;\n"
    "out float o_visibility;\n"
    "uniform sampler2D u_depth;\n"
    "uniform sampler2D u_normals;\n"
    "uniform int u_has_normals;\n"
    "uniform mat4 u_camera[2];           /* [0]: inverse view-projection, [1]: view (one upload) */\n"
    "uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;\n"
    "                                      z: the near plane's depth (1 with reverse-Z), w: a far depth\n"
    "                                      on every pixel's ray (0.5 when the far plane is at infinity) */\n"
    "uniform vec4 u_contact;             /* contact shadows (desc.contact_length): x the march's length in\n"
    "                                      world units (0: off), y its steps, z the thickness */\n"
    "uniform mat4 u_view_proj;           /* the camera's view-projection, the inverse of u_camera[0] */\n"
    "\n"
    "vec3 mask_world(ivec2 px, float d)\n"
    "{\n"
    "    vec2 ndc_xy = (vec2(px) + 0.5) / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;\n"
    "    vec4 w = u_camera[0] * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    return w.xyz / w.w;\n"
    "}\n"
    "\n"
    "float mask_view_depth(vec3 world) { return -(u_camera[1] * vec4(world, 1.0)).z; }\n"
    "\n"
    "/* one pixel's view-depth step across the receiver: the largest one-sided\n"
    "   difference to its four neighbours (those inside the frame). At a depth\n"
    "   edge it is the jump, which turns the march off on the edge's pixels,\n"
    "   where the buffer's rounding to pixel centres is widest; at a caster's\n"
    "   foot the depth is continuous and the step small. */\n"
    "float receiver_depth_step(ivec2 px, float z)\n"
    "{\n"
    "    ivec2 last = textureSize(u_depth, 0) - 1;\n"
    "    float g = 0.0;\n"
    "    for (int a = 0; a < 2; a++) {\n"
    "        ivec2 e = ivec2(1 - a, a);\n"
    "        ivec2 lo = clamp(px - e, ivec2(0), last), hi = clamp(px + e, ivec2(0), last);\n"
    "        float dl = abs(mask_view_depth(mask_world(lo, texelFetch(u_depth, lo, 0).r)) - z);\n"
    "        float dh = abs(mask_view_depth(mask_world(hi, texelFetch(u_depth, hi, 0).r)) - z);\n"
    "        g = max(g, max(lo == px ? 0.0 : dl, hi == px ? 0.0 : dh));\n"
    "    }\n"
    "    return g;\n"
    "}\n"
    "\n"
    "/* Contact shadows: a short march from the receiver toward the light through\n"
    "   the depth buffer (screen-space ray marching, as in McGuire and Mara 2014's\n"
    "   depth-buffer ray casting with a constant thickness). A sample is blocked\n"
    "   when the buffer's surface at its pixel lies in front of it by less than\n"
    "   the thickness (a thin caster throws no endless shadow behind it) and is\n"
    "   not the receiver's own surface. A pixel centre off the sample's exact\n"
    "   position on a plane the camera grazes lies far in front of or behind the\n"
    "   sample, so depth alone cannot tell the receiver's ground from a caster;\n"
    "   with normals, planes can: the buffer's point must lie off the receiver's\n"
    "   plane by more than 1/1000 of the view depth, and the sample must not lie\n"
    "   in front of the buffer surface's own plane (the foot of a lit wall\n"
    "   marching out over the ground). Without normals the buffer must lie in\n"
    "   front by more than two of the receiver's pixel depth steps.\n"
    "   0 blocked, 1 clear. */\n"
    "float contact_visibility(vec3 world, vec3 n, ivec2 px, float z)\n"
    "{\n"
    "    vec2 size = vec2(textureSize(u_depth, 0));\n"
    "    bool plane = u_has_normals != 0;\n"
    "    float tol = plane ? sk_receiver_slack : 2.0 * receiver_depth_step(px, z) + sk_receiver_slack;\n"
    "    float plane_tol = 1e-3 * z + sk_receiver_slack;\n"
    "    int steps = int(u_contact.y);\n"
    "    for (int i = 1; i <= steps; i++) {\n"
    "        vec3 p = world - sk_light_dir * (u_contact.x * float(i) / float(steps));\n"
    "        vec4 c = u_view_proj * vec4(p, 1.0);\n"
    "        if (c.w <= 0.0) break;\n"
    "        vec2 win = (c.xy / c.w * 0.5 + 0.5) * size;\n"
    "        if (any(lessThan(win, vec2(0.0))) || any(greaterThanEqual(win, size))) break;\n"
    "        ivec2 q = ivec2(win);\n"
    "        vec3 b = mask_world(q, texelFetch(u_depth, q, 0).r);\n"
    "        float in_front = mask_view_depth(p) - mask_view_depth(b);\n"
    "        if (in_front <= tol || in_front >= u_contact.z) continue;\n"
    "        if (!plane) return 0.0;\n"
    "        if (dot(b - world, n) > plane_tol && dot(b - p, normalize(texelFetch(u_normals, q, 0).xyz)) >= 0.0)\n"
    "            return 0.0;\n"
    "    }\n"
    "    return 1.0;\n"
    "}\n"
    "\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float d = texelFetch(u_depth, px, 0).r;\n"
    "    bool background = u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0;\n"
    "    /* background: done, except where sk_shadow() needs screen derivatives\n"
    "       (RMSM's level of detail; the receiver's plane without normals), which\n"
    "       need every pixel of a 2x2 quad (both conditions are uniform: this\n"
    "       branch keeps the control flow uniform) */\n"
    "    if (background && sk_rmsm == 0 && u_has_normals != 0) { o_visibility = 1.0; return; }\n"
    "    vec2 ndc_xy = gl_FragCoord.xy / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;\n"
    "    vec4 w = u_camera[0] * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    vec3 world = w.xyz / w.w;\n"
    "    /* the position four float ulps of depth away: the receiver's uncertainty */\n"
    "    vec4 w2 = u_camera[0] * vec4(ndc_xy, (d + 4.0 * d / 8388608.0) * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    sk_receiver_slack = distance(w2.xyz / w2.w, world);\n"
    "    vec3 n = u_has_normals != 0 ? normalize(texelFetch(u_normals, px, 0).xyz) : vec3(0.0);\n"
    "    float view_depth = -(u_camera[1] * vec4(world, 1.0)).z;\n"
    "    float v = sk_shadow(world, n, view_depth);\n"
    "    if (u_contact.x > 0.0 && !background && v > 0.0) v = min(v, contact_visibility(world, n, px, view_depth));\n"
    "    o_visibility = background ? 1.0 : v;\n"
    "}\n"
    ;
static const char skgl__src_ferko_analyze_frag[] =
    "/* Resolution estimation, first pass (Ferko 2013, Sec. 3): each\n"
    "   output texel covers a 4x4 block of camera pixels. Per pixel: the world\n"
    "   point from its window depth, in the light's clip space; samples outside\n"
    "   the light frustum are discarded (Sec. 3.1). Per kept pixel: its light-clip\n"
    "   xy bounds the crop, and the axis-aligned extent of its patch, the four\n"
    "   pixel corners projected with depth averaged over the pixels that share\n"
    "   each corner (Sec. 3.2), gives the smallest texel the view needs; the\n"
    "   corners are taken relative to the pixel centre for float precision.\n"
    "   The same definition as sk_estimate_resolution on the CPU.\n"
    "   Per kept pixel also its view depth, so that the same reduction gives\n"
    "   the depth range the view holds (what sample distribution shadow maps\n"
    "   split, Lauritzen, Salvi and Lefohn 2011).\n"
    "   Out: o_bounds = (min x, min y, -max x, -max y) and\n"
    "        o_patch  = (min patch width, min patch height, min view depth,\n"
    "                    -max view depth); \"none\" is +SK_BIG in every channel. A\n"
    "   MIN reduction (ferko_reduce.frag) takes both to one texel. */\n"
    "uniform sampler2D u_depth;           /* window depth, row 0 at the bottom */\n"
    "uniform mat4 u_ndc_to_light;         /* light view-projection * inverse camera view-projection */\n"
    "uniform vec4 u_world_w;              /* row 3 of the inverse camera view-projection */\n"
    "uniform int u_depth_only;            /* 1: only the bounds and the view depths (AUTO, fit_to_depth): no patch */\n"
    "uniform vec4 u_view_z;               /* row 2 of the inverse camera projection: view z = dot(u_view_z, ndc) / dot(u_world_w, ndc) */\n"
    "uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;\n"
    "                                      z: the near plane's depth (1 with reverse-Z), w: a far depth\n"
    "                                      on every pixel's ray (0.5 when the far plane is at infinity) */\n"
    "layout(location = 0) out vec4 o_bounds;\n"
    "layout(location = 1) out vec4 o_patch;\n"
    "\n"
    "const float SK_BIG = 3.0e38;\n"
    "\n"
    "float sk_depth_at(ivec2 p, ivec2 size)\n"
    "{\n"
    "    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) return -1.0;\n"
    "    float d = texelFetch(u_depth, p, 0).r;\n"
    "    return d >= 0.0 && d <= 1.0 && (u_depth_map.z == 0.0 ? d < 1.0 : d > 0.0) ? d : -1.0;\n"
    "}\n"
    "\n"
    "/* light clip of NDC (x, y, z), with the sign of the homogeneous world w folded in */\n"
    "vec4 sk_to_light(vec3 ndc)\n"
    "{\n"
    "    vec4 h = vec4(ndc, 1.0);\n"
    "    vec4 l = u_ndc_to_light * h;\n"
    "    float ww = dot(u_world_w, h);\n"
    "    if (ww < 0.0) l = -l;\n"
    "    if (ww == 0.0) l.w = 0.0;\n"
    "    return l;\n"
    "}\n"
    "\n"
    "void main()\n"
    "{\n"
    "    ivec2 size = textureSize(u_depth, 0);\n"
    "    ivec2 base = ivec2(gl_FragCoord.xy) * 4;\n"
    "    vec2 to_ndc = 2.0 / vec2(size);\n"
    "    float d[36];                     /* pixels base-1 .. base+4, 6 x 6 */\n"
    "    float cz[25];                    /* corners base .. base+4, 5 x 5: NDC z of the averaged depth, or 2 (none) */\n"
    "    vec4 b = vec4(SK_BIG), pt = vec4(SK_BIG);\n"
    "    int x, y, k;\n"
    "    if (u_depth_only != 0) {\n"
    "        /* the 16 pixels of the block alone: no neighbours, no corners */\n"
    "        for (y = 0; y < 4; y++)\n"
    "            for (x = 0; x < 4; x++) {\n"
    "                float dp = sk_depth_at(base + ivec2(x, y), size);\n"
    "                if (dp < 0.0) continue;\n"
    "                vec3 c = vec3((vec2(base + ivec2(x, y)) + 0.5) * to_ndc - 1.0, dp * u_depth_map.x + u_depth_map.y);\n"
    "                float ww = dot(u_world_w, vec4(c, 1.0));\n"
    "                vec4 l = sk_to_light(c);\n"
    "                if (!(l.w > 0.0) || any(greaterThan(abs(l.xyz), vec3(l.w)))) continue;\n"
    "                vec2 p = l.xy / l.w;\n"
    "                b = min(b, vec4(p, -p));\n"
    "                float depth = -dot(u_view_z, vec4(c, 1.0)) / ww;\n"
    "                pt.zw = min(pt.zw, vec2(depth, -depth));\n"
    "            }\n"
    "        o_bounds = b;\n"
    "        o_patch = pt;\n"
    "        return;\n"
    "    }\n"
    "    for (y = 0; y < 6; y++)\n"
    "        for (x = 0; x < 6; x++) d[y * 6 + x] = sk_depth_at(base + ivec2(x - 1, y - 1), size);\n"
    "    for (y = 0; y < 5; y++)\n"
    "        for (x = 0; x < 5; x++) {\n"
    "            /* corner base + (x, y) touches pixels (x-1..x, y-1..y): d[y..y+1][x..x+1] */\n"
    "            float s = 0.0, n = 0.0, v;\n"
    "            v = d[y * 6 + x];           if (v >= 0.0) { s += v; n += 1.0; }\n"
    "            v = d[y * 6 + x + 1];       if (v >= 0.0) { s += v; n += 1.0; }\n"
    "            v = d[(y + 1) * 6 + x];     if (v >= 0.0) { s += v; n += 1.0; }\n"
    "            v = d[(y + 1) * 6 + x + 1]; if (v >= 0.0) { s += v; n += 1.0; }\n"
    "            cz[y * 5 + x] = n > 0.0 ? (s * (1.0 / n)) * u_depth_map.x + u_depth_map.y : 2.0;\n"
    "        }\n"
    "    for (y = 0; y < 4; y++)\n"
    "        for (x = 0; x < 4; x++) {\n"
    "            float dp = d[(y + 1) * 6 + x + 1];\n"
    "            if (dp < 0.0) continue;\n"
    "            vec3 c = vec3((vec2(base + ivec2(x, y)) + 0.5) * to_ndc - 1.0, dp * u_depth_map.x + u_depth_map.y);\n"
    "            float ww = dot(u_world_w, vec4(c, 1.0));\n"
    "            vec4 l = sk_to_light(c);\n"
    "            if (!(l.w > 0.0) || any(greaterThan(abs(l.xyz), vec3(l.w)))) continue;\n"
    "            vec2 p = l.xy / l.w;\n"
    "            b = min(b, vec4(p, -p));\n"
    "            float depth = -dot(u_view_z, vec4(c, 1.0)) / ww;\n"
    "            pt.zw = min(pt.zw, vec2(depth, -depth));\n"
    "            /* the patch: its four corners relative to the pixel centre,\n"
    "               (C.xy P.w - P.xy C.w) / (C.w P.w) with C = P + M delta, so the\n"
    "               extent comes from small differences, not from subtracting\n"
    "               nearly equal light-clip positions (float has no room for that) */\n"
    "            vec2 lo = vec2(SK_BIG), hi = vec2(-SK_BIG);\n"
    "            bool ok = true;\n"
    "            for (k = 0; k < 4; k++) {\n"
    "                int kx = k & 1, ky = k >> 1, ci = (y + ky) * 5 + x + kx;\n"
    "                if (cz[ci] > 1.5) { ok = false; break; }\n"
    "                vec3 delta = vec3((vec2(kx, ky) - 0.5) * to_ndc, cz[ci] - c.z);\n"
    "                vec4 md = u_ndc_to_light * vec4(delta, 0.0);\n"
    "                float cw = dot(u_world_w, vec4(c + delta, 1.0));\n"
    "                if (ww < 0.0) md = -md;\n"
    "                vec4 cl = l + md;\n"
    "                if (!(cl.w > 0.0) || cw * ww <= 0.0) { ok = false; break; }\n"
    "                vec2 q = (md.xy * l.w - l.xy * md.w) / (cl.w * l.w);\n"
    "                lo = min(lo, q);\n"
    "                hi = max(hi, q);\n"
    "            }\n"
    "            if (ok) pt.xy = min(pt.xy, hi - lo);\n"
    "        }\n"
    "    o_bounds = b;\n"
    "    o_patch = pt;\n"
    "}\n"
    ;
static const char skgl__src_ferko_reduce_frag[] =
    "/* Resolution estimation, reduction (Ferko 2013, Sec. 3.3): the\n"
    "   MIN of the analysis texels, layer 0 the bounds stored as (min x, min y,\n"
    "   -max x, -max y), so one MIN serves both ends, layer 1 the patch. Texels\n"
    "   outside the source level's u_src_size are skipped.\n"
    "   SK_FERKO_FINAL 0: each output texel reduces a 16x16 block of the source\n"
    "   into the two layers of the next level (attachments 0 and 1).\n"
    "   SK_FERKO_FINAL 1: the last pass, over a source of at most 32x32 texels,\n"
    "   into one 2x1 RGBA32F texture: texel 0 the bounds, texel 1 the patch, so\n"
    "   that one glReadPixels of 2x1 texels reads the whole estimate. */\n"
    "uniform sampler2DArray u_src;\n"
    "uniform ivec2 u_src_size;\n"
    "#if SK_FERKO_FINAL\n"
    "out vec4 o_result;\n"
    "#else\n"
    "layout(location = 0) out vec4 o_bounds;\n"
    "layout(location = 1) out vec4 o_patch;\n"
    "#endif\n"
    "void main()\n"
    "{\n"
    "#if SK_FERKO_FINAL\n"
    "    const int n = 32;\n"
    "    ivec2 base = ivec2(0);\n"
    "#else\n"
    "    const int n = 16;\n"
    "    ivec2 base = ivec2(gl_FragCoord.xy) * 16;\n"
    "#endif\n"
    "    vec4 b = vec4(3.0e38), p = vec4(3.0e38);\n"
    "    for (int y = 0; y < n; y++)\n"
    "        for (int x = 0; x < n; x++) {\n"
    "            ivec2 q = base + ivec2(x, y);\n"
    "            if (q.x >= u_src_size.x || q.y >= u_src_size.y) continue;\n"
    "            b = min(b, texelFetch(u_src, ivec3(q, 0), 0));\n"
    "            p = min(p, texelFetch(u_src, ivec3(q, 1), 0));\n"
    "        }\n"
    "#if SK_FERKO_FINAL\n"
    "    o_result = gl_FragCoord.x < 1.0 ? b : p;\n"
    "#else\n"
    "    o_bounds = b;\n"
    "    o_patch = p;\n"
    "#endif\n"
    "}\n"
    ;
static const char skgl__src_rmsm_analyze_frag[] =
    "/* RMSM page analysis, per pixel (after Lefohn, Sengupta and Owens 2007): the\n"
    "   world point from window depth, its coordinates (s, t) in the virtual\n"
    "   shadow map of u_virtual_res^2 texels, and the level of detail\n"
    "   lod = log2(sqrt(|dX x dY|)) from the screen derivatives of the texel\n"
    "   coordinates (sk_rmsm_lod). The derivatives are those the lookup in\n"
    "   shadow_sample.glsl takes, so both choose the same page.\n"
    "   Out: (s, t, lod, 1), or 0 where nothing needs the map. */\n"
    "uniform sampler2D u_depth;\n"
    "uniform mat4 u_inv_view_proj;\n"
    "uniform mat4 u_light;            /* world -> the virtual map's light clip */\n"
    "uniform float u_virtual_res;\n"
    "uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;\n"
    "                                      z: the near plane's depth (1 with reverse-Z), w: a far depth\n"
    "                                      on every pixel's ray (0.5 when the far plane is at infinity) */\n"
    "out vec4 o_sample;\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float d = texelFetch(u_depth, px, 0).r;\n"
    "    vec2 ndc_xy = gl_FragCoord.xy / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;\n"
    "    vec4 w = u_inv_view_proj * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    vec4 c = u_light * vec4(w.xyz / w.w, 1.0);\n"
    "    vec2 st = c.xy / c.w * 0.5 + 0.5;\n"
    "    /* derivatives first, in uniform control flow */\n"
    "    vec2 dx = dFdx(st) * u_virtual_res, dy = dFdy(st) * u_virtual_res;\n"
    "    float tr = dot(dx, dx) + dot(dy, dy), det = abs(dx.x * dy.y - dx.y * dy.x);\n"
    "    float lod = log2(max(det / max(sqrt(0.5 * (tr + sqrt(max(tr * tr - 4.0 * det * det, 0.0)))), 1e-30), 1e-30));\n"
    "    bool ok = (u_depth_map.z == 0.0 ? d < 1.0 : d > 0.0) && all(greaterThanEqual(st, vec2(0.0))) && all(lessThan(st, vec2(1.0))) &&\n"
    "              abs(c.z) <= c.w;\n"
    "    o_sample = ok ? vec4(st, lod, 1.0) : vec4(0.0);\n"
    "}\n"
    ;
static const char skgl__src_rmsm_request_vert[] =
    "/* RMSM page requests, reduced on the GPU: one point per pixel of the\n"
    "   analysis texture, drawn onto the texel of the page it needs in the\n"
    "   request atlas, so every page asked for by any pixel ends up set. Level l\n"
    "   needs clamp(floor(lod), 0, u_levels - 1), as sk_rmsm_page_requests\n"
    "   takes it; when the page pool is short, the CPU folds the requests of\n"
    "   the finest levels into their ancestors (the same pages a raised minimum\n"
    "   level would request, from the one read-back). Atlas layout: level\n"
    "   l's n_l = u_pages0 >> l pages per side start at column 2 u_pages0 - 2 n_l;\n"
    "   the atlas is (2 u_pages0 - 1) x u_pages0 texels.\n"
    "   u_bands > 1 (banded requests): the atlas in RGBA8, cleared to 1 and\n"
    "   blended by MIN, two points per sample: one onto that texel with blue 0,\n"
    "   one onto its level-0 page with (f, 254 - f) / 255 in red and green, f\n"
    "   the level above: per level-0 page the least and the greatest level its\n"
    "   samples ask for. Request band b's pages follow on the CPU\n"
    "   (skgl__rmsm_bands): band 0 the level f (blue), band b > 0 at most\n"
    "   level u_levels - 1 - b (and one level finer where the pool holds\n"
    "   it), each the ancestor of the sample's level-0 page. */\n"
    "uniform sampler2D u_samples;\n"
    "uniform int u_pages0;\n"
    "uniform int u_levels;\n"
    "uniform int u_bands;\n"
    "flat out vec3 v_request;\n"
    "void main()\n"
    "{\n"
    "    ivec2 size = textureSize(u_samples, 0);\n"
    "    int i = u_bands > 1 ? gl_VertexID / 2 : gl_VertexID;\n"
    "    vec4 s = texelFetch(u_samples, ivec2(i % size.x, i / size.x), 0);\n"
    "    gl_PointSize = 1.0;\n"
    "    v_request = u_bands > 1 ? vec3(1.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);\n"
    "    if (s.w < 0.5) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }   /* outside: clipped */\n"
    "    int level = clamp(int(floor(s.z)), 0, u_levels - 1);\n"
    "    if (u_bands > 1 && gl_VertexID % 2 == 1) {\n"
    "        v_request = vec3(float(level), float(254 - level), 255.0) / 255.0;\n"
    "        level = 0;\n"
    "    }\n"
    "    int n = u_pages0 >> level;\n"
    "    ivec2 page = min(ivec2(s.xy * float(n)), ivec2(n - 1));\n"
    "    vec2 texel = vec2(float(2 * u_pages0 - 2 * n + page.x), float(page.y)) + 0.5;\n"
    "    gl_Position = vec4(texel / vec2(float(2 * u_pages0 - 1), float(u_pages0)) * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_rmsm_request_frag[] =
    "/* RMSM page requests: a set texel is a requested page (banded: the\n"
    "   levels, rmsm_request.vert). */\n"
    "flat in vec3 v_request;\n"
    "out vec4 o_request;\n"
    "void main()\n"
    "{\n"
    "    o_request = vec4(v_request, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_point_sample_glsl[] =
    "/* shadowkit: point-light (omnidirectional) shadow lookup, shared by the\n"
    "   deferred point mask pass and forward shaders (skgl_point_glsl_snippet()).\n"
    "   King & Newhall 2004.\n"
    "\n"
    "   Two storages, chosen at compile time: define SK_POINT_VSDCT 1 before this\n"
    "   text for the Virtual Shadow Depth Cube Texture, leave it undefined (or 0)\n"
    "   for the native depth cube map.\n"
    "   - cube: GL_TEXTURE_CUBE_MAP of depth, samplerCubeShadow looked up with the\n"
    "     light-to-point vector; hardware 2x2 comparison (seamless cube filtering\n"
    "     when GL_TEXTURE_CUBE_MAP_SEAMLESS is on, as the mask pass sets it).\n"
    "   - VSDCT: the six faces as sub-rects of one 2D depth atlas; an RG16\n"
    "     indirection cube map, bilinearly filtered, turns the direction into the\n"
    "     atlas (u, v) (face selection, side divide, (s, t) remap, scale and face\n"
    "     offset in one lookup, King & Newhall Fig. 5.4.7), kept half a texel inside the\n"
    "     face so a 2x2 comparison never reads across a seam (King & Newhall: \"Sampling\n"
    "     across Cube Map Seams\"); then sampler2DShadow in the atlas. Where RG16\n"
    "     textures are missing (OpenGL ES 3.0, WebGL2), SK_POINT_VSDCT_ANALYTIC 1\n"
    "     computes the same (u, v) in the shader (the indirection is not used).\n"
    "   Both store window depth per Eq. (5.4.6): z = scale / MA + bias, MA the\n"
    "   major-axis component of the light-to-point vector (the eye depth in the\n"
    "   face that holds it), so both compare the same way.\n"
    "\n"
    "   Bias (sk_point_bias_mode): 0, the receiver plane (the default): each tap\n"
    "   compares the depth that the receiver's tangent plane has along the tap's\n"
    "   own direction (where that ray meets the plane), less the plane's depth\n"
    "   change over the one texel a hardware 2x2 comparison reaches in each face\n"
    "   axis, times (1 + sk_point_plane_bias); the receiver is not moved, so no\n"
    "   shadow is displaced (after Dou, Yan, Kerzner, Dai and Wyman 2014). 1,\n"
    "   normal offset: the receiver is pushed along its normal by\n"
    "   sk_point_normal_bias texels of its face at its distance (a face texel is\n"
    "   2 MA / resolution wide), which moves shadow edges toward the light. In\n"
    "   both, casters were drawn with slope-scaled polygon offset. Filtering: one\n"
    "   hardware 2x2 comparison, or a (2r)x(2r) grid of them spaced one texel in\n"
    "   the face plane; a tap that leaves the face reads the neighbouring face\n"
    "   (its direction picks it), compared with the receiver's depth along that\n"
    "   face's axis. A surface facing away from the light (given a normal) is in\n"
    "   its own shadow: 0. Beyond sk_point_range: 1 (no shadow from this light;\n"
    "   attenuation is the shader's business).\n"
    "\n"
    "   Spot lights (SK_POINT_SPOT 1, which implies SK_POINT_VSDCT 1): one perspective\n"
    "   map down the spot's axis in sk_point_faces[0]'s rectangle of the atlas,\n"
    "   sk_point_spot (light-relative position -> the map's clip space) and\n"
    "   sk_point_basis (the map's right, up and axis) in place of the six faces;\n"
    "   MA is the depth along the axis, so Eq. (5.4.6) and both biases hold as\n"
    "   they are. Outside the cone (cosine below sk_point_cos): 0, the spot\n"
    "   does not light it. */\n"
    "#ifndef SK_POINT_VSDCT\n"
    "#define SK_POINT_VSDCT 0\n"
    "#endif\n"
    "#ifndef SK_POINT_SPOT\n"
    "#define SK_POINT_SPOT 0\n"
    "#endif\n"
    "#if SK_POINT_SPOT   /* a spot's map lives in a VSDCT atlas */\n"
    "#undef SK_POINT_VSDCT\n"
    "#define SK_POINT_VSDCT 1\n"
    "#endif\n"
    "#ifndef SK_POINT_VSDCT_ANALYTIC\n"
    "#define SK_POINT_VSDCT_ANALYTIC 0\n"
    "#endif\n"
    "uniform vec3 sk_point_pos;          /* light position, world */\n"
    "uniform float sk_point_range;       /* far plane of the faces */\n"
    "uniform vec2 sk_point_depth;        /* Eq. (5.4.6): (scale, bias) of sk_vsdct_depth_coeffs */\n"
    "uniform float sk_point_texel;       /* 2 / face resolution: one texel at MA = 1 */\n"
    "uniform float sk_point_normal_bias; /* texels (mode 1; mode 0 adds it if > 0) */\n"
    "uniform int sk_point_bias_mode;     /* 0 receiver plane, 1 normal offset */\n"
    "uniform float sk_point_plane_bias;  /* mode 0: extra tolerance, in texels of the plane's depth slope */\n"
    "/* How far (world units) the receiver position may lie from the true\n"
    "   surface: the deferred mask sets it from its depth buffer's precision\n"
    "   before calling sk_point_shadow(); 0 for a forward shader's positions */\n"
    "float sk_point_receiver_slack = 0.0;\n"
    "uniform int sk_point_pcf;           /* 0: one 2x2 comparison; r: (2r)^2 of them */\n"
    "#if SK_POINT_VSDCT\n"
    "uniform highp sampler2DShadow sk_point_atlas;\n"
    "uniform highp samplerCube sk_point_indirection;\n"
    "uniform vec4 sk_point_faces[6];     /* per face: its sub-rect inset by half a texel, (u0, v0, u1, v1) */\n"
    "#else\n"
    "uniform highp samplerCubeShadow sk_point_cube;\n"
    "#endif\n"
    "#if SK_POINT_SPOT\n"
    "uniform mat4 sk_point_spot;         /* light-relative position -> the map's clip space */\n"
    "uniform mat4 sk_point_basis;        /* columns: the map's right, up and axis (world), 0 */\n"
    "uniform float sk_point_cos;         /* cosine of the cone's half-angle */\n"
    "#endif\n"
    "\n"
    "/* the major-axis component of |v| along the axis that d's face looks down */\n"
    "float sk_point_ma(vec3 av, vec3 d)\n"
    "{\n"
    "    vec3 ad = abs(d);\n"
    "    if (ad.x >= ad.y && ad.x >= ad.z) return av.x;\n"
    "    return ad.y >= ad.z ? av.y : av.z;\n"
    "}\n"
    "\n"
    "/* MA of the light-relative point v itself: its major-axis component, or\n"
    "   for a spot its depth along the axis */\n"
    "float sk_point_ma_of(vec3 v)\n"
    "{\n"
    "#if SK_POINT_SPOT\n"
    "    return dot(v, sk_point_basis[2].xyz);\n"
    "#else\n"
    "    vec3 av = abs(v);\n"
    "    return max(av.x, max(av.y, av.z));\n"
    "#endif\n"
    "}\n"
    "\n"
    "/* one hardware 2x2 comparison of depth ref along direction d */\n"
    "float sk_point_tap(vec3 d, float ref)\n"
    "{\n"
    "#if SK_POINT_SPOT\n"
    "    /* the map's clip space, into face 0's rectangle (its full extent is the\n"
    "       inset one grown by half a texel), clamped inside it */\n"
    "    vec4 c = sk_point_spot * vec4(d, 1.0);\n"
    "    vec4 r = sk_point_faces[0];\n"
    "    vec2 st = 0.5 * c.xy / c.w + 0.5;\n"
    "    vec2 texel = 1.0 / vec2(textureSize(sk_point_atlas, 0));\n"
    "    vec2 uv = clamp(r.xy - 0.5 * texel + st * (r.zw - r.xy + texel), r.xy, r.zw);\n"
    "    return texture(sk_point_atlas, vec3(uv, ref));\n"
    "#elif SK_POINT_VSDCT\n"
    "    /* the indirection keeps (u, v) half a texel inside the face, but its 16\n"
    "       bits round to 1/65535 of the atlas: clamped again here, in float, or\n"
    "       the 2x2 filter could give a neighbouring sub-rect a sliver of weight */\n"
    "    vec3 ad = abs(d);\n"
    "    int f = ad.x >= ad.y && ad.x >= ad.z ? (d.x >= 0.0 ? 0 : 1) : ad.y >= ad.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5);\n"
    "    vec4 r = sk_point_faces[f];\n"
    "#if SK_POINT_VSDCT_ANALYTIC\n"
    "    /* the indirection's arithmetic in the shader (no RG16 texture, which\n"
    "       OpenGL ES 3.0 and WebGL2 lack): (s, t) on the face's axes (the GL\n"
    "       cube map convention, sk_cube_face_view's), then into the face's\n"
    "       sub-rect, whose full extent is the inset one grown by half a texel */\n"
    "    const vec3 sk_axis_s[6] = vec3[6](vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0),\n"
    "                                      vec3(1.0, 0.0, 0.0), vec3(1.0, 0.0, 0.0), vec3(-1.0, 0.0, 0.0));\n"
    "    const vec3 sk_axis_t[6] = vec3[6](vec3(0.0, -1.0, 0.0), vec3(0.0, -1.0, 0.0), vec3(0.0, 0.0, 1.0),\n"
    "                                      vec3(0.0, 0.0, -1.0), vec3(0.0, -1.0, 0.0), vec3(0.0, -1.0, 0.0));\n"
    "    float ma = max(ad.x, max(ad.y, ad.z));\n"
    "    vec2 st = 0.5 * vec2(dot(sk_axis_s[f], d), dot(sk_axis_t[f], d)) / ma + 0.5;\n"
    "    vec2 texel = 1.0 / vec2(textureSize(sk_point_atlas, 0));\n"
    "    vec2 uv = clamp(r.xy - 0.5 * texel + st * (r.zw - r.xy + texel), r.xy, r.zw);\n"
    "#else\n"
    "    vec2 uv = clamp(texture(sk_point_indirection, d).rg, r.xy, r.zw);\n"
    "#endif\n"
    "    return texture(sk_point_atlas, vec3(uv, ref));\n"
    "#else\n"
    "    return texture(sk_point_cube, vec4(d, ref));\n"
    "#endif\n"
    "}\n"
    "\n"
    "/* the major-axis distance (MA, Eq. 5.4.6's) at which the receiver's\n"
    "   tangent plane (normal n through v, both relative to the light) meets the\n"
    "   ray along direction d, the ray's distance to the plane kept within\n"
    "   [1/2, 2] of v's (at grazing incidence the plane leaves the tap's\n"
    "   neighbourhood) */\n"
    "float sk_point_plane_ma(vec3 v, vec3 n, vec3 d)\n"
    "{\n"
    "    float t = dot(n, v) / dot(n, d);\n"
    "    float t0 = sk_point_ma_of(v) / max(sk_point_ma_of(d), 1e-30);\n"
    "    t = clamp(t, 0.5 * t0, 2.0 * t0);\n"
    "    return t * sk_point_ma_of(d);\n"
    "}\n"
    "\n"
    "/* one tap along d compared with the receiver plane: the plane's window\n"
    "   depth along d (Eq. 5.4.6), less its change over one texel in each face\n"
    "   axis (t1, t2 of length one texel at d). The change is taken on the\n"
    "   distances, |dz/dMA| = |scale| / MA^2 times the change of MA: a difference\n"
    "   of two window depths near 1 would keep only a few bits (and none on GPUs\n"
    "   whose division is not correctly rounded). */\n"
    "float sk_point_plane_tap(vec3 v, vec3 n, vec3 d, vec3 t1, vec3 t2)\n"
    "{\n"
    "    float m = max(sk_point_plane_ma(v, n, d), 1e-30);\n"
    "    float z = sk_point_depth.x / m + sk_point_depth.y;\n"
    "    float dz_dma = abs(sk_point_depth.x) / (m * m);\n"
    "    float slope = dz_dma * (abs(sk_point_plane_ma(v, n, d + t1) - m) + abs(sk_point_plane_ma(v, n, d + t2) - m));\n"
    "    /* the receiver's own uncertainty: dz/dMA = -scale / MA^2 at v */\n"
    "    float ma = sk_point_ma_of(v);\n"
    "    float slack = abs(sk_point_depth.x) / max(ma * ma, 1e-30) * sk_point_receiver_slack;\n"
    "    return sk_point_tap(d, z - (1.0 + sk_point_plane_bias) * slope - slack - 4.0e-7);\n"
    "}\n"
    "\n"
    "float sk_point_shadow(vec3 world_pos, vec3 world_normal)\n"
    "{\n"
    "    vec3 v = world_pos - sk_point_pos;\n"
    "    float dist = length(v);\n"
    "    if (!(dist > 0.0) || dist > sk_point_range) return 1.0;\n"
    "    if (dot(world_normal, v) >= 0.0 && dot(world_normal, world_normal) > 0.0) return 0.0;\n"
    "#if SK_POINT_SPOT\n"
    "    if (dot(v, sk_point_basis[2].xyz) < sk_point_cos * dist) return 0.0;\n"
    "#endif\n"
    "    vec3 av = abs(v);\n"
    "    float ma = sk_point_ma_of(v);\n"
    "    bool plane = sk_point_bias_mode == 0 && dot(world_normal, world_normal) > 0.0;\n"
    "    vec3 n = world_normal;\n"
    "    if (sk_point_bias_mode == 1 || sk_point_normal_bias > 0.0)\n"
    "        v += world_normal * (sk_point_normal_bias * sk_point_texel * ma);\n"
    "    av = abs(v);\n"
    "    ma = sk_point_ma_of(v);\n"
    "    if (!(ma > 0.0)) return 1.0;\n"
    "    /* the face plane's axes at v (any two axes other than the major one;\n"
    "       a spot's map's right and up) */\n"
    "    vec3 t1, t2;\n"
    "#if SK_POINT_SPOT\n"
    "    t1 = sk_point_basis[0].xyz; t2 = sk_point_basis[1].xyz;\n"
    "#else\n"
    "    if (av.x >= av.y && av.x >= av.z) { t1 = vec3(0.0, 0.0, 1.0); t2 = vec3(0.0, 1.0, 0.0); }\n"
    "    else if (av.y >= av.z) { t1 = vec3(1.0, 0.0, 0.0); t2 = vec3(0.0, 0.0, 1.0); }\n"
    "    else { t1 = vec3(1.0, 0.0, 0.0); t2 = vec3(0.0, 1.0, 0.0); }\n"
    "#endif\n"
    "    float step = sk_point_texel * ma;\n"
    "    if (sk_point_pcf <= 0)\n"
    "        return plane ? sk_point_plane_tap(v, n, v, t1 * step, t2 * step)\n"
    "                     : sk_point_tap(v, sk_point_depth.x / ma + sk_point_depth.y);\n"
    "    int r = sk_point_pcf;\n"
    "    float sum = 0.0;\n"
    "    for (int y = -r; y < r; y++)\n"
    "        for (int x = -r; x < r; x++) {\n"
    "            vec3 d = v + (t1 * (float(x) + 0.5) + t2 * (float(y) + 0.5)) * step;\n"
    "            if (plane) {\n"
    "                sum += sk_point_plane_tap(v, n, d, t1 * step, t2 * step);\n"
    "            } else {\n"
    "#if SK_POINT_SPOT\n"
    "                float m = max(ma, 1e-30);\n"
    "#else\n"
    "                float m = max(sk_point_ma(av, d), 1e-30);\n"
    "#endif\n"
    "                sum += sk_point_tap(d, sk_point_depth.x / m + sk_point_depth.y);\n"
    "            }\n"
    "        }\n"
    "    return sum / float(4 * r * r);\n"
    "}\n"
    ;
static const char skgl__src_point_mask_frag[] =
    "/* Deferred point-light shadow mask: camera depth (and optional world\n"
    "   normals) in, visibility out (1 lit, 0 shadowed). World positions from\n"
    "   window depth exactly as shadow_mask.frag reconstructs them. The pass runs\n"
    "   inside the light's scissor rectangle (sk_light_scissor) when asked: the\n"
    "   pixels outside it are not written. */\n"
    "in vec2 v_uv;\n"
    "out float o_visibility;\n"
    "uniform sampler2D u_depth;\n"
    "uniform sampler2D u_normals;\n"
    "uniform int u_has_normals;\n"
    "uniform mat4 u_inv_view_proj;\n"
    "uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;\n"
    "                                      z: the near plane's depth (1 with reverse-Z), w: a far depth\n"
    "                                      on every pixel's ray (0.5 when the far plane is at infinity) */\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float d = texelFetch(u_depth, px, 0).r;\n"
    "    if (u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0) { o_visibility = 1.0; return; }\n"
    "    vec2 ndc_xy = gl_FragCoord.xy / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;\n"
    "    vec4 w = u_inv_view_proj * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    vec3 world = w.xyz / w.w;\n"
    "    /* the position four float ulps of depth away: the receiver's uncertainty */\n"
    "    vec4 w2 = u_inv_view_proj * vec4(ndc_xy, (d + 4.0 * d / 8388608.0) * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    sk_point_receiver_slack = distance(w2.xyz / w2.w, world);\n"
    "    vec3 n = u_has_normals != 0 ? normalize(texelFetch(u_normals, px, 0).xyz) : vec3(0.0);\n"
    "    o_visibility = sk_point_shadow(world, n);\n"
    "}\n"
    ;
static const char skgl__src_soft_common_glsl[] =
    "/* Area-light soft shadows (Shen et al. 2011): what the kernel-shape pass and the\n"
    "   PCSS mask share. The light is a rectangle at u_light_pos facing along\n"
    "   the -z axis of its view (sk_mat4_look_at); its shadow maps are\n"
    "   perspective projections from the rectangle's centre (u_light_vp, the\n"
    "   base frustum; PVSM tiles are crops of it, which keep its depth).\n"
    "   Kernels and footprints are in the base frustum's NDC (clip units,\n"
    "   2 across a map), depths in window units [0,1]. */\n"
    "uniform sampler2D u_depth;        /* camera window depth */\n"
    "uniform sampler2D u_normals;      /* world normals in .xyz */\n"
    "uniform int u_has_normals;\n"
    "uniform mat4 u_inv_view_proj;\n"
    "uniform mat4 u_light_vp;\n"
    "uniform vec3 u_light_pos;\n"
    "uniform vec2 u_light_half;        /* world half sizes along the light's x and y */\n"
    "uniform vec4 u_light_proj;        /* P00, P11, near, far of the base frustum */\n"
    "uniform float u_rel_bias;         /* comparison tolerance, relative to the light distance */\n"
    "uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;\n"
    "                                      z: the near plane's depth (1 with reverse-Z), w: a far depth\n"
    "                                      on every pixel's ray (0.5 when the far plane is at infinity) */\n"
    "\n"
    "vec3 sk_unproject(vec2 frag, float d)\n"
    "{\n"
    "    vec2 ndc = frag / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;\n"
    "    vec4 w = u_inv_view_proj * vec4(ndc, d * u_depth_map.x + u_depth_map.y, 1.0);\n"
    "    return w.xyz / w.w;\n"
    "}\n"
    "\n"
    "/* eye distance along the light's axis from window depth */\n"
    "float sk_light_linear(float win)\n"
    "{\n"
    "    float n = u_light_proj.z, f = u_light_proj.w, z = win * 2.0 - 1.0;\n"
    "    return 2.0 * n * f / ((f + n) - z * (f - n));\n"
    "}\n"
    "\n"
    "/* the light's window-depth tolerance at eye distance z: u_rel_bias * z,\n"
    "   through d(win)/dz = n f / ((f - n) z^2) */\n"
    "float sk_light_tolerance(float z)\n"
    "{\n"
    "    float n = u_light_proj.z, f = u_light_proj.w;\n"
    "    return u_rel_bias * n * f / ((f - n) * z);\n"
    "}\n"
    "\n"
    "/* base-frustum NDC xy and window depth of a world point; w <= 0: behind */\n"
    "vec4 sk_light_project(vec3 p)\n"
    "{\n"
    "    vec4 c = u_light_vp * vec4(p, 1.0);\n"
    "    if (c.w <= 1e-12) return vec4(0.0, 0.0, 0.0, -1.0);\n"
    "    vec3 ndc = c.xyz / c.w;\n"
    "    return vec4(ndc.xy, ndc.z * 0.5 + 0.5, c.w);\n"
    "}\n"
    "\n"
    "/* the receiver of one pixel, seen from the light */\n"
    "struct sk_receiver {\n"
    "    vec3 world, normal;\n"
    "    vec4 light;       /* ndc xy, window depth, clip w (<= 0: behind the light) */\n"
    "    vec2 du, dv;      /* half-axes of the pixel footprint on the map (Fig. 5) */\n"
    "    vec2 grad;        /* window depth per NDC unit along the receiver's plane */\n"
    "    float zlin;       /* distance along the light's axis */\n"
    "    bool facing;      /* the receiver faces the light's centre */\n"
    "};\n"
    "\n"
    "vec3 sk_gbuffer_normal(ivec2 px, vec3 world, float d)\n"
    "{\n"
    "    if (u_has_normals != 0) {\n"
    "        vec3 n = texelFetch(u_normals, px, 0).xyz;\n"
    "        if (dot(n, n) > 0.0) return normalize(n);\n"
    "    }\n"
    "    /* none given: the plane through the neighbours on the nearer side */\n"
    "    ivec2 size = textureSize(u_depth, 0);\n"
    "    ivec2 pxr = ivec2(min(px.x + 1, size.x - 1), px.y), pxl = ivec2(max(px.x - 1, 0), px.y);\n"
    "    ivec2 pyu = ivec2(px.x, min(px.y + 1, size.y - 1)), pyd = ivec2(px.x, max(px.y - 1, 0));\n"
    "    float dr = texelFetch(u_depth, pxr, 0).r, dl = texelFetch(u_depth, pxl, 0).r;\n"
    "    float du_ = texelFetch(u_depth, pyu, 0).r, dd = texelFetch(u_depth, pyd, 0).r;\n"
    "    vec3 ex = abs(dr - d) < abs(dl - d) ? sk_unproject(vec2(pxr) + 0.5, dr) - world\n"
    "                                        : world - sk_unproject(vec2(pxl) + 0.5, dl);\n"
    "    vec3 ey = abs(du_ - d) < abs(dd - d) ? sk_unproject(vec2(pyu) + 0.5, du_) - world\n"
    "                                         : world - sk_unproject(vec2(pyd) + 0.5, dd);\n"
    "    vec3 n = cross(ex, ey);\n"
    "    return dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);\n"
    "}\n"
    "\n"
    "/* where the ray through a screen point meets the receiver's tangent plane\n"
    "   (the affine approximation of the mapping M, Sec. 4.2) */\n"
    "vec3 sk_on_plane(vec2 frag, vec3 p, vec3 n)\n"
    "{\n"
    "    /* the ray from the near plane to the far one (to a point on it when the far plane is at infinity) */\n"
    "    vec3 o = sk_unproject(frag, u_depth_map.z), e = sk_unproject(frag, u_depth_map.w), dir = e - o;\n"
    "    float den = dot(n, dir);\n"
    "    if (abs(den) < 1e-6 * length(dir)) return p;\n"
    "    float t = dot(n, p - o) / den;\n"
    "    return o + clamp(t, 0.0, u_depth_map.z + u_depth_map.w == 1.0 ? 1.0 : 1e30) * dir;\n"
    "}\n"
    "\n"
    "sk_receiver sk_receiver_at(ivec2 px, float d)\n"
    "{\n"
    "    sk_receiver r;\n"
    "    vec2 frag = vec2(px) + 0.5;\n"
    "    r.world = sk_unproject(frag, d);\n"
    "    r.normal = sk_gbuffer_normal(px, r.world, d);\n"
    "    r.light = sk_light_project(r.world);\n"
    "    r.zlin = r.light.w;\n"
    "    r.facing = dot(r.normal, r.normal) == 0.0 || dot(r.normal, u_light_pos - r.world) > 0.0;\n"
    "    r.du = vec2(0.0); r.dv = vec2(0.0); r.grad = vec2(0.0);\n"
    "    if (r.light.w <= 0.0 || dot(r.normal, r.normal) == 0.0) return r;\n"
    "    vec4 lx = sk_light_project(sk_on_plane(frag + vec2(1.0, 0.0), r.world, r.normal));\n"
    "    vec4 ly = sk_light_project(sk_on_plane(frag + vec2(0.0, 1.0), r.world, r.normal));\n"
    "    if (lx.w <= 0.0 || ly.w <= 0.0) return r;\n"
    "    /* a grazing view stretches the footprint without bound: cap it */\n"
    "    vec2 ax = clamp(lx.xy - r.light.xy, vec2(-0.25), vec2(0.25));\n"
    "    vec2 ay = clamp(ly.xy - r.light.xy, vec2(-0.25), vec2(0.25));\n"
    "    r.du = 0.5 * ax;\n"
    "    r.dv = 0.5 * ay;\n"
    "    /* window depth is affine in NDC over a plane: solve [ax; ay] g = dz */\n"
    "    float det = ax.x * ay.y - ax.y * ay.x;\n"
    "    if (abs(det) > 1e-14) {\n"
    "        float zx = lx.z - r.light.z, zy = ly.z - r.light.z;\n"
    "        r.grad = vec2(zx * ay.y - zy * ax.y, ax.x * zy - ay.x * zx) / det;\n"
    "    }\n"
    "    return r;\n"
    "}\n"
    "\n"
    "/* Sec. 4: the soft shadowing filter s_alpha on the map plane for a blocker\n"
    "   at distance zo, as half-axes (light rectangle aligned with the map) */\n"
    "vec2 sk_filter_half(float zy, float zo)\n"
    "{\n"
    "    float k = max(zy - zo, 0.0) / (zy * zo);\n"
    "    return vec2(u_light_proj.x * u_light_half.x, u_light_proj.y * u_light_half.y) * k;\n"
    "}\n"
    ;
static const char skgl__src_soft_kernel_frag[] =
    "/* PVSM steps 3 and the first half of 4 (Sec. 4 to 5.1): per pixel, the\n"
    "   blocker search on the conservative low-resolution map's MIN pyramid, the\n"
    "   filter s_alpha from the average blocker depth, its convolution with the\n"
    "   warped pixel footprint (appendix), and the predicted texel size (Eqs. 4\n"
    "   and 5). Background pixels are discarded (the target keeps its clear\n"
    "   state 0; the SMTG pass counts the covered pixels from it).\n"
    "   o_kernel: u_h.x, u_h.y, v_h.y (v_h.x is 0), state\n"
    "             (1 fully lit, 2 in penumbra or umbra: filter, 3 faces away: 0)\n"
    "   o_pred:   NDC x, y on the base map, r0, r1 (Eq. 5, clip units per texel)\n"
    "   o_plane:  window depth, its NDC gradient, tolerance */\n"
    "in vec2 v_uv;\n"
    "layout(location = 0) out vec4 o_kernel;\n"
    "layout(location = 1) out vec4 o_pred;\n"
    "layout(location = 2) out vec4 o_plane;\n"
    "uniform sampler2D u_lowres;       /* R32F MIN pyramid of the low-res map's window depth (conservative) */\n"
    "uniform sampler2D u_lowres_true;  /* R32F, the same map rasterised plainly */\n"
    "uniform int u_lowres_size;\n"
    "uniform int u_lowres_levels;\n"
    "uniform int u_blocker_cells;      /* per axis */\n"
    "uniform int u_static_scene;\n"
    "uniform int u_hard;               /* zero-size light: the 1:1 criterion */\n"
    "uniform float u_res_scale;        /* predicted resolutions times this */\n"
    "uniform float u_antialias;        /* 1: the filter is h, the pixel footprint included (Sec. 4.2);\n"
    "                                     0: the filter is s_alpha alone (point samples) */\n"
    "\n"
    "float sk_rho(float n)\n"
    "{\n"
    "    /* Shen et al. 2011, Sec. 5.1, clamped at the cubic's peak as sk_rho_dynamic/static */\n"
    "    float x = log2(max(n, 1.0));\n"
    "    if (u_static_scene != 0) {\n"
    "        x = min(x, 10.6085);\n"
    "        return 0.5477 + x * (1.406 + x * (-0.04687 - 0.003944 * x));\n"
    "    }\n"
    "    x = min(x, 10.6262);\n"
    "    return 0.667 + x * (0.7794 + x * (0.3967 - 0.02716 * x));\n"
    "}\n"
    "\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float d = texelFetch(u_depth, px, 0).r;\n"
    "    if (u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0) discard;\n"
    "    sk_receiver r = sk_receiver_at(px, d);\n"
    "    float tol = sk_light_tolerance(max(r.zlin, 1e-6));\n"
    "    o_plane = vec4(r.light.z, r.grad, tol);\n"
    "    o_pred = vec4(r.light.xy, 1e30, 1e30);\n"
    "    if (r.light.w <= 0.0 || any(greaterThan(abs(r.light.xy), vec2(1.0))) || r.light.z > 1.0) {\n"
    "        o_kernel = vec4(0.0, 0.0, 0.0, 1.0);      /* outside the light's frustum: lit */\n"
    "        return;\n"
    "    }\n"
    "    if (!r.facing) { o_kernel = vec4(0.0, 0.0, 0.0, 3.0); return; }\n"
    "\n"
    "    /* blocker search region: the pyramid from the receiver to the light cut\n"
    "       by the near plane, grown by the footprint */\n"
    "    /* the near plane is the nearest the bounds come; the casters over this\n"
    "       receiver may be much farther: the region's own minimum (coarse levels\n"
    "       of the pyramid) moves the cut down, which only shrinks the region */\n"
    "    float zs = u_light_proj.z;\n"
    "    for (int it = 0; it < 3; it++) {\n"
    "        vec2 reg = sk_filter_half(r.zlin, zs) + abs(r.du) + abs(r.dv);\n"
    "        float t = max(reg.x, reg.y) * float(u_lowres_size);\n"
    "        int lv = clamp(int(ceil(log2(max(t, 1.0)))), 0, u_lowres_levels - 1);\n"
    "        int nc = max(u_lowres_size >> lv, 1);\n"
    "        float cz = 2.0 / float(nc);\n"
    "        ivec2 a = clamp(ivec2(floor((r.light.xy - reg + 1.0) / cz)), ivec2(0), ivec2(nc - 1));\n"
    "        ivec2 b = clamp(ivec2(floor((r.light.xy + reg + 1.0) / cz)), ivec2(0), ivec2(nc - 1));\n"
    "        float m = 1.0;\n"
    "        for (int y = a.y; y <= b.y; y++)\n"
    "            for (int x = a.x; x <= b.x; x++)\n"
    "                m = min(m, texelFetch(u_lowres, ivec2(x, y), lv).r);\n"
    "        /* nothing in the cells nearer than the receiver's plane anywhere\n"
    "           over them: no blocker, fully lit (most pixels end here). Texels\n"
    "           left at the clear depth 1 hold nothing: a steep receiver's plane\n"
    "           carried across the region can pass the far plane (> 1), and\n"
    "           must not make empty texels blockers, here and below */\n"
    "        if (it == 0 && m >= min(r.light.z + abs(r.grad.x) * (reg.x + cz) + abs(r.grad.y) * (reg.y + cz) - tol, 1.0)) {\n"
    "            o_kernel = vec4(0.0, 0.0, 0.0, 1.0);\n"
    "            return;\n"
    "        }\n"
    "        float zm = clamp(sk_light_linear(m), zs, r.zlin);\n"
    "        if (zm <= zs * 1.001) break;\n"
    "        zs = zm;\n"
    "    }\n"
    "    vec2 region = sk_filter_half(r.zlin, zs) + abs(r.du) + abs(r.dv);\n"
    "    float texels = max(region.x, region.y) * float(u_lowres_size);   /* full width in texels */\n"
    "    int level = clamp(int(ceil(log2(max(texels / float(u_blocker_cells), 1.0)))), 0, u_lowres_levels - 1);\n"
    "    int cells = max(u_lowres_size >> level, 1);\n"
    "    float cs = 2.0 / float(cells);                 /* cell side in NDC */\n"
    "    ivec2 c0 = clamp(ivec2(floor((r.light.xy - region + 1.0) / cs)), ivec2(0), ivec2(cells - 1));\n"
    "    ivec2 c1 = clamp(ivec2(floor((r.light.xy + region + 1.0) / cs)), ivec2(0), ivec2(cells - 1));\n"
    "    /* the plane's lowest depth over the cell, and over the half texel the\n"
    "       conservative rasteriser extends a triangle past its edges */\n"
    "    float slack = (abs(r.grad.x) + abs(r.grad.y)) * (cs * 0.5 + 1.0 / float(u_lowres_size)) + tol;\n"
    "    float sum = 0.0, count = 0.0;\n"
    "    for (int y = c0.y; y <= c1.y; y++)\n"
    "        for (int x = c0.x; x <= c1.x; x++) {\n"
    "            vec2 centre = (vec2(x, y) + 0.5) * cs - 1.0;\n"
    "            float m = texelFetch(u_lowres, ivec2(x, y), level).r;\n"
    "            float plane = r.light.z + dot(r.grad, centre - r.light.xy) - slack;\n"
    "            if (m < min(plane, 1.0)) { sum += sk_light_linear(m); count += 1.0; }\n"
    "        }\n"
    "    if (count == 0.0) { o_kernel = vec4(0.0, 0.0, 0.0, 1.0); return; }   /* fully lit */\n"
    "    /* the cells' minima decide \"fully lit\" conservatively but pull the\n"
    "       average towards the nearest blocker of each cell: the average comes\n"
    "       from point samples of the plainly rasterised map (no grown borders\n"
    "       with their extended depths), or of the conservative one when that\n"
    "       finds none (casters thinner than a texel) */\n"
    "    {\n"
    "        float nb = float(u_blocker_cells);\n"
    "        float pslack = (abs(r.grad.x) + abs(r.grad.y)) * 2.0 / float(u_lowres_size) + tol;\n"
    "        vec2 ps = vec2(0.0), pc = vec2(0.0);      /* plain, conservative */\n"
    "        for (int y = 0; y < u_blocker_cells; y++)\n"
    "            for (int x = 0; x < u_blocker_cells; x++) {\n"
    "                vec2 o = ((vec2(x, y) + 0.5) / nb * 2.0 - 1.0) * region;\n"
    "                ivec2 t = clamp(ivec2((r.light.xy + o + 1.0) * 0.5 * float(u_lowres_size)), ivec2(0),\n"
    "                                ivec2(u_lowres_size - 1));\n"
    "                float plane = r.light.z + dot(r.grad, o) - pslack;\n"
    "                float mt = texelFetch(u_lowres_true, t, 0).r, mc = texelFetch(u_lowres, t, 0).r;\n"
    "                if (mt < min(plane, 1.0)) { ps.x += sk_light_linear(mt); pc.x += 1.0; }\n"
    "                if (mc < min(plane, 1.0)) { ps.y += sk_light_linear(mc); pc.y += 1.0; }\n"
    "            }\n"
    "        if (pc.x > 0.0) { sum = ps.x; count = pc.x; }\n"
    "        else if (pc.y > 0.0) { sum = ps.y; count = pc.y; }\n"
    "    }\n"
    "    float zo = min(sum / count, r.zlin);\n"
    "    vec2 s = u_hard != 0 ? vec2(0.0) : sk_filter_half(r.zlin, zo);\n"
    "    /* appendix: V_h = M_s M_s^T + M_phi M_phi^T, Cholesky columns */\n"
    "    float m00 = s.x * s.x + r.du.x * r.du.x + r.dv.x * r.dv.x;\n"
    "    float m10 = r.du.x * r.du.y + r.dv.x * r.dv.y;\n"
    "    float m11 = s.y * s.y + r.du.y * r.du.y + r.dv.y * r.dv.y;\n"
    "    float ux = sqrt(max(m00, 1e-20));\n"
    "    float uy = m10 / ux;\n"
    "    float vy = sqrt(max(m11 - uy * uy, 1e-20));\n"
    "    /* the prediction always sizes h; without anti-aliasing the filter is s_alpha alone */\n"
    "    o_kernel = u_antialias > 0.0 ? vec4(ux, uy, vy, 2.0) : vec4(max(s.x, 1e-10), 0.0, max(s.y, 1e-10), 2.0);\n"
    "\n"
    "    /* Eq. (4): kernel size in pixels along e0, e1 through M_phi^-1; Eq. (5) */\n"
    "    float det = r.du.x * r.dv.y - r.dv.x * r.du.y;\n"
    "    float n0 = abs(det) > 1e-20 ? ux * length(vec2(r.dv.y, r.du.y)) / abs(det) : 1e30;\n"
    "    float n1 = abs(det) > 1e-20 ? vy * length(vec2(r.dv.x, r.du.x)) / abs(det) : 1e30;\n"
    "    float rho0 = u_hard != 0 ? 1.0 : sk_rho(n0);\n"
    "    float rho1 = u_hard != 0 ? 1.0 : sk_rho(n1);\n"
    "    vec2 r_k = vec2(2.0 * ux / rho0, 2.0 * vy / rho1);\n"
    "    /* a receiver the light grazes has a footprint one pixel thin along one\n"
    "       axis of the map and long along the other; its demand along the thin\n"
    "       axis would cut the grid into slivers of tiles: at most 8:1 */\n"
    "    r_k = max(r_k, vec2(max(r_k.x, r_k.y) / 8.0));\n"
    "    o_pred.zw = r_k / u_res_scale;\n"
    "}\n"
    ;
static const char skgl__src_soft_smtg_vert[] =
    "/* PVSM step 3 (Sec. 5.2): one attribute-less point per screen pixel. A\n"
    "   pixel that needs filtering puts its predicted texel sizes in its SMTG\n"
    "   cell, where MIN blending keeps the smallest (red, green) and additive\n"
    "   blending counts the pixels (alpha). Every other covered pixel (fully lit,\n"
    "   facing away, outside the light) is counted in the row above the grid,\n"
    "   spread over its cells. Background pixels fall outside the clip volume.\n"
    "   The target is grid x (grid + 1) texels: one read-back brings the SMTG and\n"
    "   the counts of stats.lit_fraction. */\n"
    "uniform sampler2DArray u_screen;  /* layers: kernel, prediction, plane */\n"
    "uniform int u_width;\n"
    "uniform int u_grid;\n"
    "flat out vec2 v_r;\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_VertexID % u_width, gl_VertexID / u_width);\n"
    "    vec4 k = texelFetch(u_screen, ivec3(px, 0), 0);\n"
    "    vec4 p = texelFetch(u_screen, ivec3(px, 1), 0);\n"
    "    float g = float(u_grid);\n"
    "    vec2 cell;\n"
    "    gl_PointSize = 1.0;\n"
    "    v_r = p.zw;\n"
    "    if (k.w == 0.0) {\n"
    "        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);\n"
    "        return;\n"
    "    }\n"
    "    if (k.w != 2.0 || any(greaterThan(abs(p.xy), vec2(1.0)))) {\n"
    "        v_r = vec2(1e30);\n"
    "        cell = vec2(float(px.x % u_grid), g);\n"
    "    } else {\n"
    "        cell = min(floor((p.xy * 0.5 + 0.5) * g), vec2(g - 1.0));\n"
    "    }\n"
    "    gl_Position = vec4((cell + 0.5) / vec2(g, g + 1.0) * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_soft_smtg_frag[] =
    "/* PVSM step 3: the point's predicted texel sizes (MIN-blended) and a count\n"
    "   of one (added). */\n"
    "flat in vec2 v_r;\n"
    "out vec4 o_r;\n"
    "void main()\n"
    "{\n"
    "    o_r = vec4(v_r, 1e30, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_soft_reduce_vert[] =
    "/* One level of PVSM's low-resolution MIN pyramid per triangle, all from one\n"
    "   program: triangle k (vertices 3k..3k+2, glDrawArrays' first) draws level\n"
    "   k + 1. The viewport is level 1's; the triangle covers level k + 1's\n"
    "   texels, the lower-left 1/2^k of it. */\n"
    "flat out int v_level;\n"
    "void main()\n"
    "{\n"
    "    int k = gl_VertexID / 3, v = gl_VertexID - 3 * k;\n"
    "    vec2 p = vec2(float((v << 1) & 2), float(v & 2));\n"
    "    v_level = k + 1;\n"
    "    gl_Position = vec4(p * (2.0 / float(1 << k)) - 1.0, 0.0, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_soft_reduce_frag[] =
    "/* One level of a MIN pyramid stored as the mip chain of u_src: each texel\n"
    "   the minimum of the 2x2 texels of the level below (odd sizes: the missing\n"
    "   ones are skipped). Only the level below is read (texelFetch), never the\n"
    "   one drawn; with a non-mipmap sampler on u_src, only the base level would\n"
    "   be a rendering feedback loop. */\n"
    "uniform sampler2D u_src;\n"
    "flat in int v_level;\n"
    "layout(location = 0) out vec4 o_min;\n"
    "#ifdef SKGL_REDUCE_COPY\n"
    "/* skgl_caps.mip_render_level 0 (WebGL2: ANGLE refuses to sample a texture\n"
    "   while one of its levels is drawn, whatever the sampler): u_src is a\n"
    "   single-level copy of the level below, and this level goes to a copy too */\n"
    "layout(location = 1) out vec4 o_copy;\n"
    "#define SKGL_SRC_LEVEL 0\n"
    "#else\n"
    "#define SKGL_SRC_LEVEL (v_level - 1)\n"
    "#endif\n"
    "void main()\n"
    "{\n"
    "    ivec2 d = ivec2(gl_FragCoord.xy) * 2, size = textureSize(u_src, SKGL_SRC_LEVEL);\n"
    "    vec4 m = vec4(1e30);\n"
    "    for (int y = 0; y < 2; y++)\n"
    "        for (int x = 0; x < 2; x++) {\n"
    "            ivec2 s = d + ivec2(x, y);\n"
    "            if (s.x < size.x && s.y < size.y) m = min(m, texelFetch(u_src, s, SKGL_SRC_LEVEL));\n"
    "        }\n"
    "    o_min = m;\n"
    "#ifdef SKGL_REDUCE_COPY\n"
    "    o_copy = m;\n"
    "#endif\n"
    "}\n"
    ;
static const char skgl__src_soft_filter_frag[] =
    "/* PVSM step 8 (Sec. 4.1, 4.2, 5.2) for one tile: the smooth texel-coverage\n"
    "   integration of the pixel's kernel h over the tile's map. Texels are\n"
    "   quads; the semi-axis-aligned parallelogram is cut into vertical panels\n"
    "   one texel wide, each taken as an axis-aligned box. Only the part of the\n"
    "   kernel inside the tile counts; the output (V*A, A) is added into the\n"
    "   accumulation target, so kernels spanning several tiles merge as\n"
    "   V = sum(V_i A_i) / sum(A_i). Kernels wider than 24 texels are integrated\n"
    "   over blocks of 2^k texels, each tested with one hardware 2x2 comparison\n"
    "   at its centre (for k = 1 that covers the block), so a blocker's edge is\n"
    "   resolved to a block, not a texel. A block is never larger than the texel\n"
    "   the prediction asked for this pixel (o_pred.zw, Eq. 5, divided by the\n"
    "   resolution scale): the tile may be finer than that (another pixel's\n"
    "   demand, or a resolution scale above 1), and a block sized by the kernel\n"
    "   alone (1/24 of it) would discard that resolution once rho(n) > 12 or the\n"
    "   scale > 1. At most 128 blocks per axis, whatever is asked. */\n"
    "in vec2 v_uv;\n"
    "out vec4 o_acc;\n"
    "uniform sampler2DArray u_screen;  /* layers: kernel, prediction, plane */\n"
    "uniform sampler2DShadow u_tile;   /* window depth, LEQUAL comparison; the tile fills [0, res) of it */\n"
    "uniform vec4 u_tile_rect;         /* NDC x0, y0, x1, y1 of the tile on the base map */\n"
    "uniform vec2 u_tile_res;\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    vec4 k = texelFetch(u_screen, ivec3(px, 0), 0);\n"
    "    if (k.w != 2.0) discard;\n"
    "    vec4 pr = texelFetch(u_screen, ivec3(px, 1), 0);\n"
    "    vec4 pl = texelFetch(u_screen, ivec3(px, 2), 0);\n"
    "    float ux = k.x, uy = k.y, vy = k.z;\n"
    "    vec2 c = pr.xy;\n"
    "    if (c.x + ux <= u_tile_rect.x || c.x - ux >= u_tile_rect.z ||\n"
    "        c.y + abs(uy) + vy <= u_tile_rect.y || c.y - abs(uy) - vy >= u_tile_rect.w)\n"
    "        discard;\n"
    "    vec2 scale = u_tile_res / (u_tile_rect.zw - u_tile_rect.xy);     /* texels per NDC unit */\n"
    "    vec2 ct = (c - u_tile_rect.xy) * scale;\n"
    "    float uxt = ux * scale.x, uyt = uy * scale.y, vyt = vy * scale.y;\n"
    "    float x0 = max(ct.x - uxt, 0.0), x1 = min(ct.x + uxt, u_tile_res.x);\n"
    "    float span = max(2.0 * uxt, 2.0 * vyt);\n"
    "    float need = min(pr.z * scale.x, pr.w * scale.y);         /* this pixel's texel, in tile texels */\n"
    "    float stride = min(exp2(max(ceil(log2(span / 24.0)), 0.0)), exp2(max(floor(log2(need)), 0.0)));\n"
    "    stride = max(stride, exp2(max(ceil(log2(span / 128.0)), 0.0)));\n"
    "    vec2 tex_size = vec2(textureSize(u_tile, 0));\n"
    "    float slack = (abs(pl.y) / scale.x + abs(pl.z) / scale.y) * stride * 0.5 + pl.w;\n"
    "    float lit = 0.0, area = 0.0;\n"
    "    for (float tx = floor(x0 / stride) * stride; tx < x1; tx += stride) {\n"
    "        float px0 = max(tx, x0), px1 = min(tx + stride, x1);\n"
    "        if (px1 <= px0) continue;\n"
    "        float a = (0.5 * (px0 + px1) - ct.x) / uxt;\n"
    "        float yc = ct.y + a * uyt;\n"
    "        float py0 = max(yc - vyt, 0.0), py1 = min(yc + vyt, u_tile_res.y);\n"
    "        for (float ty = floor(py0 / stride) * stride; ty < py1; ty += stride) {\n"
    "            float cov = (px1 - px0) * (min(ty + stride, py1) - max(ty, py0));\n"
    "            if (cov <= 0.0) continue;\n"
    "            vec2 t = min(vec2(tx, ty) + 0.5 * stride, u_tile_res - 0.5);\n"
    "            vec2 ndc = u_tile_rect.xy + t / scale;\n"
    "            float plane = pl.x + dot(pl.yz, ndc - c) - slack;\n"
    "            area += cov;\n"
    "            /* a plane past the far plane (> 1) must not shadow the empty texels (1) */\n"
    "            lit += cov * texture(u_tile, vec3(t / tex_size, min(plane, 1.0)));\n"
    "        }\n"
    "    }\n"
    "    if (area <= 0.0) discard;\n"
    "    float a_ndc = area / (scale.x * scale.y);\n"
    "    o_acc = vec4(lit / area * a_ndc, a_ndc, 0.0, 0.0);\n"
    "}\n"
    ;
static const char skgl__src_soft_resolve_frag[] =
    "/* PVSM: the visibility mask from the kernel states and the accumulated\n"
    "   (V*A, A) of every tile (Sec. 5.2). */\n"
    "in vec2 v_uv;\n"
    "out float o_visibility;\n"
    "uniform sampler2DArray u_screen;  /* layer 0: the kernel */\n"
    "uniform sampler2D u_acc;\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float state = texelFetch(u_screen, ivec3(px, 0), 0).w;\n"
    "    vec2 acc = texelFetch(u_acc, px, 0).xy;\n"
    "    if (state == 3.0) o_visibility = 0.0;\n"
    "    else if (state == 2.0 && acc.y > 0.0) o_visibility = clamp(acc.x / acc.y, 0.0, 1.0);\n"
    "    else o_visibility = 1.0;\n"
    "}\n"
    ;
static const char skgl__src_soft_cons_geom[] =
    "/* PVSM step 2: conservative rasterisation after Hasselgren et al. (GPU\n"
    "   Gems 2, ch. 42, second algorithm): every edge is pushed out by the\n"
    "   semi-diagonal of a texel, so each texel the triangle touches gets a\n"
    "   fragment; the fragment stage clips the overfill at the corners with the\n"
    "   triangle's bounding box grown by half a texel. Depth is the triangle's\n"
    "   own plane, extended; the fragment stage also gets the original edges,\n"
    "   so that it can tell the triangle's own texels from the grown border.\n"
    "   Triangles crossing the light's plane (w <= 0) are passed through\n"
    "   unchanged. skgl_conservative = 0: plain rasterisation.\n"
    "   A caster program's varyings (SKGL_CASTER_VARYINGS) reach each emitted\n"
    "   vertex through skgl_caster_varyings(b, s, k) (defined after this source,\n"
    "   its inputs indexed by constants only): s the corner's barycentric weights\n"
    "   on the original vertices, extrapolated from its NDC position (what a\n"
    "   noperspective varying interpolates linearly in the window), b the same\n"
    "   weighted by 1/w so that the rasteriser's perspective-correct\n"
    "   interpolation (the corner is emitted at w = 1 / sum(b / w)) gives the\n"
    "   values the original triangle would have there (smooth and centroid\n"
    "   varyings); k the vertex whose value a flat varying takes: the grown\n"
    "   triangle's three corners all take the last vertex's, GL's default\n"
    "   provoking vertex (the only one in GLSL ES), a triangle passed through\n"
    "   keeps each vertex's own. */\n"
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 3) out;\n"
    "uniform vec2 skgl_texel;          /* 2 / resolution: one texel in NDC */\n"
    "uniform int skgl_conservative;\n"
    "flat out vec4 skgl_box;           /* window-space box of the fragments kept */\n"
    "flat out vec3 skgl_edge[3];       /* the original edges in window space: inside when dot(xy, e) <= z */\n"
    "#ifdef SKGL_CASTER_VARYINGS\n"
    "void skgl_caster_varyings(vec3 b, vec3 s, int k);\n"
    "#endif\n"
    "void main()\n"
    "{\n"
    "    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position, c2 = gl_in[2].gl_Position;\n"
    "    /* outputs are undefined after EmitVertex: every vertex sets them all */\n"
    "    vec4 box = vec4(-1e30, -1e30, 1e30, 1e30);\n"
    "    vec3 edge[3] = vec3[3](vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0));\n"
    "    if (skgl_conservative == 0 || min(c0.w, min(c1.w, c2.w)) <= 1e-6) {\n"
    "        for (int i = 0; i < 3; i++) {\n"
    "            skgl_box = box;\n"
    "            skgl_edge = edge;\n"
    "#ifdef SKGL_CASTER_VARYINGS\n"
    "            vec3 u = vec3(i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0);\n"
    "            skgl_caster_varyings(u, u, i);\n"
    "#endif\n"
    "            gl_Position = gl_in[i].gl_Position;\n"
    "            EmitVertex();\n"
    "        }\n"
    "        EndPrimitive();\n"
    "        return;\n"
    "    }\n"
    "    vec3 p[3] = vec3[3](c0.xyz / c0.w, c1.xyz / c1.w, c2.xyz / c2.w);\n"
    "    float area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);\n"
    "    if (area == 0.0) return;\n"
    "    bool swapped = area < 0.0;\n"
    "    if (swapped) { vec3 t = p[1]; p[1] = p[2]; p[2] = t; area = -area; }\n"
    "    vec2 h = 0.5 * skgl_texel;\n"
    "    /* depth plane z = A x + B y + C through the three vertices */\n"
    "    vec2 e1 = p[1].xy - p[0].xy, e2 = p[2].xy - p[0].xy;\n"
    "    float dz1 = p[1].z - p[0].z, dz2 = p[2].z - p[0].z;\n"
    "    float A = (dz1 * e2.y - dz2 * e1.y) / area, B = (e1.x * dz2 - e2.x * dz1) / area;\n"
    "    /* offset edge lines n.x = d, n the outward normal of edge i -> i+1 */\n"
    "    vec2 n[3]; float dist[3];\n"
    "    vec2 vp = 1.0 / skgl_texel;   /* NDC -> window: (x + 1) * res / 2 */\n"
    "    for (int i = 0; i < 3; i++) {\n"
    "        vec2 e = p[(i + 1) % 3].xy - p[i].xy;\n"
    "        n[i] = vec2(e.y, -e.x);\n"
    "        dist[i] = dot(n[i], p[i].xy);\n"
    "        /* n.x <= d in NDC is (n / vp).w <= d + n.x + n.y in window space */\n"
    "        edge[i] = vec3(n[i] / vp, dist[i] + n[i].x + n[i].y);\n"
    "        dist[i] += abs(n[i].x) * h.x + abs(n[i].y) * h.y;\n"
    "    }\n"
    "    vec2 lo = min(p[0].xy, min(p[1].xy, p[2].xy)) - h, hi = max(p[0].xy, max(p[1].xy, p[2].xy)) + h;\n"
    "    box = vec4((lo + 1.0) * vp, (hi + 1.0) * vp);\n"
    "    for (int i = 0; i < 3; i++) {\n"
    "        int j = (i + 2) % 3;      /* the edge ending at vertex i */\n"
    "        float det = n[j].x * n[i].y - n[j].y * n[i].x;\n"
    "        vec2 q = abs(det) > 1e-12 * dot(n[i], n[i]) * dot(n[j], n[j])\n"
    "                     ? vec2(dist[j] * n[i].y - dist[i] * n[j].y, n[j].x * dist[i] - n[i].x * dist[j]) / det\n"
    "                     : p[i].xy + normalize(n[i]) * length(h);\n"
    "        q = clamp(q, lo - 2.0 * (hi - lo), hi + 2.0 * (hi - lo));\n"
    "        float z = p[0].z + A * (q.x - p[0].x) + B * (q.y - p[0].y);\n"
    "        skgl_box = box;\n"
    "        skgl_edge = edge;\n"
    "#ifdef SKGL_CASTER_VARYINGS\n"
    "        vec2 d0 = q - p[0].xy, d1 = p[1].xy - p[0].xy, d2 = p[2].xy - p[0].xy;\n"
    "        vec3 b = vec3(0.0, (d0.x * d2.y - d0.y * d2.x) / area, (d1.x * d0.y - d1.y * d0.x) / area);\n"
    "        b.x = 1.0 - b.y - b.z;\n"
    "        if (swapped) b = b.xzy;\n"
    "        vec3 bw = b / vec3(c0.w, c1.w, c2.w);\n"
    "        float s = bw.x + bw.y + bw.z;\n"
    "        float W = s > 1e-20 ? 1.0 / s : 1.0;\n"
    "        skgl_caster_varyings(s > 1e-20 ? bw * W : b, b, 2);\n"
    "        gl_Position = vec4(q * W, z * W, W);\n"
    "#else\n"
    "        gl_Position = vec4(q, z, 1.0);\n"
    "#endif\n"
    "        EmitVertex();\n"
    "    }\n"
    "    EndPrimitive();\n"
    "}\n"
    ;
static const char skgl__src_soft_cons_frag[] =
    "/* PVSM step 2: window depth into two R32F targets, both MIN-blended (no\n"
    "   depth test): skgl_cons every texel the grown triangle touches (level 0 of\n"
    "   the blocker-search pyramid), skgl_true only texels whose centre the\n"
    "   original triangle covers (the plain map, for the average blocker\n"
    "   depth); overfill outside the grown bounding box discarded. A caster\n"
    "   program's fragment hook may discard first (an alpha test); every name\n"
    "   declared here starts with skgl_, reserved in the hooks. */\n"
    "flat in vec4 skgl_box;\n"
    "flat in vec3 skgl_edge[3];\n"
    "layout(location = 0) out vec4 skgl_cons;\n"
    "layout(location = 1) out vec4 skgl_true;\n"
    "layout(location = 2) out vec4 skgl_cons_copy;   /* skgl_soft's low_copy[0], where it has one */\n"
    "void main()\n"
    "{\n"
    "#ifdef SKGL_CASTER_FRAGMENT\n"
    "    skgl_caster_fragment();\n"
    "#endif\n"
    "    vec2 skgl_p = gl_FragCoord.xy;\n"
    "    if (any(lessThan(skgl_p, skgl_box.xy)) || any(greaterThan(skgl_p, skgl_box.zw))) discard;\n"
    "    bool skgl_inside = dot(skgl_p, skgl_edge[0].xy) <= skgl_edge[0].z &&\n"
    "                       dot(skgl_p, skgl_edge[1].xy) <= skgl_edge[1].z &&\n"
    "                       dot(skgl_p, skgl_edge[2].xy) <= skgl_edge[2].z;\n"
    "    skgl_cons = vec4(gl_FragCoord.z);\n"
    "    skgl_true = vec4(skgl_inside ? gl_FragCoord.z : 1.0);\n"
    "    skgl_cons_copy = skgl_cons;\n"
    "}\n"
    ;
static const char skgl__src_soft_gbuffer_vert[] =
    "/* Area-light shadows without a user G-buffer: the camera's depth and\n"
    "   world normals rendered through the draw callback (a caster program's\n"
    "   skgl_caster_position() in place of attribute 0, as in depth.vert). */\n"
    "#ifndef SKGL_CASTER\n"
    "layout(location = 0) in vec3 a_position;\n"
    "vec4 skgl_caster_position() { return vec4(a_position, 1.0); }\n"
    "#endif\n"
    "uniform mat4 skgl_view_proj;\n"
    "uniform mat4 skgl_model;\n"
    "out vec3 skgl_world;\n"
    "void main()\n"
    "{\n"
    "    vec4 skgl_w = skgl_model * skgl_caster_position();\n"
    "    skgl_world = skgl_w.xyz / skgl_w.w;\n"
    "    gl_Position = skgl_view_proj * skgl_w;\n"
    "}\n"
    ;
static const char skgl__src_soft_gbuffer_frag[] =
    "/* Flat world normals from the screen derivatives, turned to the camera. */\n"
    "in vec3 skgl_world;\n"
    "out vec4 skgl_normal;\n"
    "uniform vec3 skgl_eye;\n"
    "void main()\n"
    "{\n"
    "#ifdef SKGL_CASTER_FRAGMENT\n"
    "    skgl_caster_fragment();\n"
    "#endif\n"
    "    vec3 skgl_n = cross(dFdx(skgl_world), dFdy(skgl_world));\n"
    "    skgl_n = dot(skgl_n, skgl_n) > 0.0 ? normalize(skgl_n) : vec3(0.0, 1.0, 0.0);\n"
    "    if (dot(skgl_n, skgl_eye - skgl_world) < 0.0) skgl_n = -skgl_n;\n"
    "    skgl_normal = vec4(skgl_n, 1.0);\n"
    "}\n"
    ;
static const char skgl__src_pcss_mask_frag[] =
    "/* Percentage-closer soft shadows (Fernando 2005, as in Shen et al. 2011, Sec. 4) on one\n"
    "   map: a blocker search of u_blocker_cells^2 point samples over the region\n"
    "   the light's pyramid cuts from the near plane, the filter s_alpha from\n"
    "   the average blocker depth (Eq. 1), and PCF over it with up to\n"
    "   u_pcf_taps^2 hardware 2x2 comparisons. Depths are compared against the\n"
    "   receiver's plane at each sample (receiver-plane depth bias). A steep\n"
    "   receiver's plane, carried across a wide kernel, can pass the far plane\n"
    "   (window depth > 1): a texel the depth pass left at its clear value 1 is\n"
    "   nothing, never a blocker, so blockers are m < min(plane, 1) and the\n"
    "   comparison reference is clamped to 1 (DEPTH_COMPONENT32F does not clamp\n"
    "   it, and 1 <= 1 is lit). */\n"
    "in vec2 v_uv;\n"
    "out float o_visibility;\n"
    "uniform sampler2D u_map;          /* window depth, no comparison */\n"
    "uniform sampler2DShadow u_map_cmp;\n"
    "uniform int u_blocker_cells;\n"
    "uniform int u_pcf_taps;\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float d = texelFetch(u_depth, px, 0).r;\n"
    "    if (u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0) { o_visibility = 1.0; return; }\n"
    "    sk_receiver r = sk_receiver_at(px, d);\n"
    "    if (r.light.w <= 0.0 || any(greaterThan(abs(r.light.xy), vec2(1.0))) || r.light.z > 1.0) {\n"
    "        o_visibility = 1.0;\n"
    "        return;\n"
    "    }\n"
    "    if (!r.facing) { o_visibility = 0.0; return; }\n"
    "    float res = float(textureSize(u_map, 0).x);\n"
    "    float tol = sk_light_tolerance(max(r.zlin, 1e-6));\n"
    "    vec2 region = sk_filter_half(r.zlin, u_light_proj.z);\n"
    "    float n = float(u_blocker_cells), sum = 0.0, count = 0.0;\n"
    "    for (int y = 0; y < u_blocker_cells; y++)\n"
    "        for (int x = 0; x < u_blocker_cells; x++) {\n"
    "            vec2 o = ((vec2(x, y) + 0.5) / n * 2.0 - 1.0) * region;\n"
    "            vec2 ndc = r.light.xy + o;\n"
    "            float m = textureLod(u_map, ndc * 0.5 + 0.5, 0.0).r;\n"
    "            float plane = r.light.z + dot(r.grad, o) - tol - (abs(r.grad.x) + abs(r.grad.y)) / res;\n"
    "            if (m < min(plane, 1.0)) { sum += sk_light_linear(m); count += 1.0; }\n"
    "        }\n"
    "    if (count == 0.0) { o_visibility = 1.0; return; }\n"
    "    vec2 s = sk_filter_half(r.zlin, min(sum / count, r.zlin));\n"
    "    /* taps one texel apart or spread evenly over the kernel, at most u_pcf_taps per axis */\n"
    "    vec2 texels = s * res;       /* half-width in texels: s NDC * res / 2, times 2 for the full width */\n"
    "    ivec2 taps = clamp(ivec2(ceil(texels)) + 1, ivec2(1), ivec2(u_pcf_taps));\n"
    "    float lit = 0.0;\n"
    "    for (int y = 0; y < taps.y; y++)\n"
    "        for (int x = 0; x < taps.x; x++) {\n"
    "            vec2 f = vec2(taps.x > 1 ? float(x) / float(taps.x - 1) : 0.5,\n"
    "                          taps.y > 1 ? float(y) / float(taps.y - 1) : 0.5);\n"
    "            vec2 o = (f * 2.0 - 1.0) * s;\n"
    "            float plane = r.light.z + dot(r.grad, o) - tol - (abs(r.grad.x) + abs(r.grad.y)) / res;\n"
    "            lit += texture(u_map_cmp, vec3((r.light.xy + o) * 0.5 + 0.5, min(plane, 1.0)));\n"
    "        }\n"
    "    o_visibility = lit / float(taps.x * taps.y);\n"
    "}\n"
    ;
static const char skgl__src_layered_geom[] =
    "/* Layered single-pass caster rendering: every triangle arrives in world\n"
    "   space (relative to the light's origin: depth.vert with SKGL_LAYERED) and\n"
    "   goes to each of the skgl_layer_count layers through that layer's\n"
    "   view-projection, into layer skgl_layer_of[i] of the layered depth target\n"
    "   (gl_Layer: a cascade of the array texture, a face of the cube map). A\n"
    "   triangle wholly outside one of a layer's clip planes skips that layer.\n"
    "   With SKGL_GS_INVOCATIONS (GL_ARB_gpu_shader5) one invocation per layer;\n"
    "   otherwise one invocation loops over the layers. A caster program's\n"
    "   varyings (SKGL_CASTER_VARYINGS) go through skgl_caster_varyings(b, s, k)\n"
    "   (defined after this source, its inputs indexed by constants only), b = s\n"
    "   the vertex's unit weight, k the vertex: each vertex keeps its own values,\n"
    "   a flat one included (the provoking vertex is the same either way). */\n"
    "#ifdef SKGL_GS_INVOCATIONS\n"
    "layout(triangles, invocations = 8) in;\n"
    "layout(triangle_strip, max_vertices = 3) out;\n"
    "#else\n"
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 24) out;\n"
    "#endif\n"
    "uniform mat4 skgl_layer_vp[8];\n"
    "uniform int skgl_layer_of[8];\n"
    "uniform int skgl_layer_count;\n"
    "#ifdef SKGL_CASTER_VARYINGS\n"
    "void skgl_caster_varyings(vec3 b, vec3 s, int k);\n"
    "#endif\n"
    "\n"
    "void skgl_layer(int i)\n"
    "{\n"
    "    vec4 c[3];\n"
    "    for (int k = 0; k < 3; k++) c[k] = skgl_layer_vp[i] * gl_in[k].gl_Position;\n"
    "    for (int a = 0; a < 3; a++) {\n"
    "        if (c[0][a] < -c[0].w && c[1][a] < -c[1].w && c[2][a] < -c[2].w) return;\n"
    "        if (c[0][a] > c[0].w && c[1][a] > c[1].w && c[2][a] > c[2].w) return;\n"
    "    }\n"
    "    for (int k = 0; k < 3; k++) {\n"
    "#ifdef SKGL_CASTER_VARYINGS\n"
    "        vec3 u = vec3(k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0);\n"
    "        skgl_caster_varyings(u, u, k);\n"
    "#endif\n"
    "        gl_Layer = skgl_layer_of[i];\n"
    "        gl_Position = c[k];\n"
    "        EmitVertex();\n"
    "    }\n"
    "    EndPrimitive();\n"
    "}\n"
    "\n"
    "void main()\n"
    "{\n"
    "#ifdef SKGL_GS_INVOCATIONS\n"
    "    if (gl_InvocationID < skgl_layer_count) skgl_layer(gl_InvocationID);\n"
    "#else\n"
    "    for (int i = 0; i < skgl_layer_count; i++) skgl_layer(i);\n"
    "#endif\n"
    "}\n"
    ;
static const char skgl__src_soft_dilate_frag[] =
    "/* PVSM step 1 without a geometry shader (OpenGL ES 3.0, WebGL2): the\n"
    "   low-resolution map was rendered u_factor times finer with plain\n"
    "   rasterisation into u_fine (window depth); each low-resolution texel takes\n"
    "   o_cons, the minimum over its u_factor x u_factor block grown by one fine\n"
    "   texel on every side (what conservative rasterisation catches of every\n"
    "   caster at least one fine texel wide; thinner ones can slip between the\n"
    "   fine texels' centres), and o_true, the minimum of the four fine texels\n"
    "   around its centre (the plain map). */\n"
    "uniform sampler2D u_fine;\n"
    "uniform int u_factor;\n"
    "layout(location = 0) out vec4 o_cons;\n"
    "layout(location = 1) out vec4 o_true;\n"
    "layout(location = 2) out vec4 o_cons_copy;   /* skgl_soft's low_copy[0], where it has one */\n"
    "void main()\n"
    "{\n"
    "    ivec2 last = textureSize(u_fine, 0) - 1;\n"
    "    ivec2 base = ivec2(gl_FragCoord.xy) * u_factor;\n"
    "    float m = 1.0;\n"
    "    for (int y = -1; y <= u_factor; y++)\n"
    "        for (int x = -1; x <= u_factor; x++)\n"
    "            m = min(m, texelFetch(u_fine, clamp(base + ivec2(x, y), ivec2(0), last), 0).r);\n"
    "    ivec2 c = base + ivec2(u_factor / 2);\n"
    "    float t = min(min(texelFetch(u_fine, c - ivec2(1, 1), 0).r, texelFetch(u_fine, c - ivec2(0, 1), 0).r),\n"
    "                  min(texelFetch(u_fine, c - ivec2(1, 0), 0).r, texelFetch(u_fine, c, 0).r));\n"
    "    o_cons = vec4(m);\n"
    "    o_true = vec4(t);\n"
    "    o_cons_copy = o_cons;\n"
    "}\n"
    ;
static const char skgl__src_evsm_moments_frag[] =
    "/* EVSM moments (exponential variance shadow maps: Lauritzen and McCool\n"
    "   2008, \"Layered Variance Shadow Maps\", Sec. 4, the exponential warp with\n"
    "   a positive and a negative exponent). One separable box filter in two\n"
    "   passes over a layer of the light's map: the horizontal pass reads the\n"
    "   depth layer, warps each texel's depth x = 2 z - 1 into\n"
    "   (exp(c+ x), exp(c+ x)^2, -exp(-c- x), exp(-c- x)^2) and averages them\n"
    "   along a row; the vertical pass (SK_EVSM_VERTICAL) averages those along a\n"
    "   column into the layer of the moments array. The box is 2 u_box.x map\n"
    "   texels wide (2r+1 for a blur of r), each texel weighed by the part of it\n"
    "   the box covers, and it is evaluated every u_box.y map texels only (the\n"
    "   output texel i at (i + 0.5) u_box.y): a wide box at a coarse spacing\n"
    "   reads about as many texels per map texel as a narrow one at the map's\n"
    "   own, and the receiver's bilinear tap fills in between. Reads clamp to\n"
    "   the texels this frame rendered (u_extent). Two draws per layer whatever\n"
    "   the width. */\n"
    "in vec2 v_uv;\n"
    "out vec4 o_moments;\n"
    "uniform vec2 u_box;                 /* x: the box's half-width, y: the output spacing, in map texels */\n"
    "uniform vec2 u_extent;              /* the rendered region, in texels of the pass's source */\n"
    "#ifdef SK_EVSM_VERTICAL\n"
    "uniform highp sampler2D u_src;      /* the horizontal pass's moments */\n"
    "#else\n"
    "uniform highp sampler2DArray u_depth;   /* the light's depth maps (no comparison) */\n"
    "uniform int u_layer;\n"
    "uniform vec2 u_exponents;           /* c+, c- */\n"
    "#endif\n"
    "\n"
    "vec4 moments_at(ivec2 t)\n"
    "{\n"
    "#ifdef SK_EVSM_VERTICAL\n"
    "    return texelFetch(u_src, t, 0);\n"
    "#else\n"
    "    float x = 2.0 * texelFetch(u_depth, ivec3(t, u_layer), 0).r - 1.0;\n"
    "    float p = exp(u_exponents.x * x), n = -exp(-u_exponents.y * x);\n"
    "    return vec4(p, p * p, n, n * n);\n"
    "#endif\n"
    "}\n"
    "\n"
    "void main()\n"
    "{\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy), last = ivec2(u_extent) - 1;\n"
    "#ifdef SK_EVSM_VERTICAL\n"
    "    int i = px.y;\n"
    "    ivec2 step = ivec2(0, 1);\n"
    "#else\n"
    "    int i = px.x;\n"
    "    ivec2 step = ivec2(1, 0);\n"
    "#endif\n"
    "    /* the box [lo, hi] along the pass's axis; texel j spans [j, j + 1] */\n"
    "    float c = (float(i) + 0.5) * u_box.y, lo = c - u_box.x, hi = c + u_box.x;\n"
    "    int first = int(floor(lo)), end = int(ceil(hi));\n"
    "    ivec2 row = px - i * step;\n"
    "    vec4 sum = vec4(0.0);\n"
    "    for (int j = first; j < end; j++) {\n"
    "        float w = min(hi, float(j + 1)) - max(lo, float(j));\n"
    "        sum += w * moments_at(clamp(row + j * step, ivec2(0), last));\n"
    "    }\n"
    "    o_moments = sum / (hi - lo);\n"
    "}\n"
    ;
/* SKGL_EMBEDDED_SHADERS_END */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif

/* the one way the code above reaches the sources; a compiled-out feature's
   (CONFIGURATION: SKGL_NO_*) are "", so its literals are never referenced
   and the compiler drops them */
#ifdef SKGL_NO_RMSM
#define SKGL__RMSM_SRC(src) ""
#else
#define SKGL__RMSM_SRC(src) src
#endif
#ifdef SKGL_NO_SOFT
#define SKGL__SOFT_SRC(src) ""
#else
#define SKGL__SOFT_SRC(src) src
#endif
#ifdef SKGL_NO_FERKO
#define SKGL__FERKO_SRC(src) ""
#else
#define SKGL__FERKO_SRC(src) src
#endif
static const char *skgl__glsl(skgl__glsl_id id)
{
    static const char *const src[SKGL__GLSL_N] = {
        skgl__src_depth_vert,
        skgl__src_depth_frag,
        skgl__src_fullscreen_vert,
        skgl__src_shadow_sample_glsl,
        skgl__src_shadow_mask_frag,
        SKGL__FERKO_SRC(skgl__src_ferko_analyze_frag),
        SKGL__FERKO_SRC(skgl__src_ferko_reduce_frag),
        SKGL__RMSM_SRC(skgl__src_rmsm_analyze_frag),
        SKGL__RMSM_SRC(skgl__src_rmsm_request_vert),
        SKGL__RMSM_SRC(skgl__src_rmsm_request_frag),
        skgl__src_point_sample_glsl,
        skgl__src_point_mask_frag,
        SKGL__SOFT_SRC(skgl__src_soft_common_glsl),
        SKGL__SOFT_SRC(skgl__src_soft_kernel_frag),
        SKGL__SOFT_SRC(skgl__src_soft_smtg_vert),
        SKGL__SOFT_SRC(skgl__src_soft_smtg_frag),
        SKGL__SOFT_SRC(skgl__src_soft_reduce_vert),
        SKGL__SOFT_SRC(skgl__src_soft_reduce_frag),
        SKGL__SOFT_SRC(skgl__src_soft_filter_frag),
        SKGL__SOFT_SRC(skgl__src_soft_resolve_frag),
        SKGL__SOFT_SRC(skgl__src_soft_cons_geom),
        SKGL__SOFT_SRC(skgl__src_soft_cons_frag),
        SKGL__SOFT_SRC(skgl__src_soft_gbuffer_vert),
        SKGL__SOFT_SRC(skgl__src_soft_gbuffer_frag),
        SKGL__SOFT_SRC(skgl__src_pcss_mask_frag),
        skgl__src_layered_geom,
        SKGL__SOFT_SRC(skgl__src_soft_dilate_frag),
        skgl__src_evsm_moments_frag,
    };
    return (int)id >= 0 && id < SKGL__GLSL_N ? src[id] : "";
}

#ifdef __cplusplus
}
#endif

#endif /* SHADOWKIT_GL_IMPLEMENTATION_INCLUDED */
#endif /* SHADOWKIT_GL_IMPLEMENTATION */

/*
------------------------------------------------------------------------------
This software is available under 2 licenses -- choose whichever you prefer.
------------------------------------------------------------------------------
ALTERNATIVE A - MIT License
Copyright (c) 2026 shadowkit authors
Permission is hereby granted, free of charge, to any person obtaining a copy of
this software and associated documentation files (the "Software"), to deal in
the Software without restriction, including without limitation the rights to
use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies
of the Software, and to permit persons to whom the Software is furnished to do
so, subject to the following conditions:
The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
------------------------------------------------------------------------------
ALTERNATIVE B - Public Domain (www.unlicense.org)
This is free and unencumbered software released into the public domain.
Anyone is free to copy, modify, publish, use, compile, sell, or distribute this
software, either in source code form or as a compiled binary, for any purpose,
commercial or non-commercial, and by any means.
In jurisdictions that recognize copyright laws, the author or authors of this
software dedicate any and all copyright interest in the software to the public
domain. We make this dedication for the benefit of the public at large and to
the detriment of our heirs and successors. We intend this dedication to be an
overt act of relinquishment in perpetuity of all present and future rights to
this software under copyright law.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER IN AN
ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN CONNECTION
WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
------------------------------------------------------------------------------
*/
