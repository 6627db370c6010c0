/* es_dump.c - the desktop side of the browser test: the ground-and-boxes
   scene, every technique's mask on desktop OpenGL 3.3 (OSMesa) and the exact
   reference of the three lights, written to the file named on the command
   line (format: esx_data_header in es_core.h), which the browser test page
   embeds. Exit status 0 when every technique ran. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "tb_gl_context.h"
#include "tb_reference.h"
#include "tb_scene.h"
#include "es/es_core.h"

static esx_run g_run;
static float g_vis[3][ESX_W * ESX_H];

static int trace_reference(const tb_scene *scene)
{
    skgl_camera cam = esx_camera();
    sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
    skgl_area_light a = esx_area_light();
    tb_reference *ref = tb_reference_create(scene);
    tb_view view;
    tb_light l[3];
    int t, bad = ref == NULL;
    memset(l, 0, sizeof l);
    sk_mat4_inverse(vp, &view.inv_view_proj);
    view.width = ESX_W;
    view.height = ESX_H;
    l[0].type = TB_LIGHT_DIRECTIONAL;
    l[0].direction = esx_sun_dir();
    l[1].type = TB_LIGHT_POINT;
    l[1].position = esx_point_pos();
    l[1].range = esx_point_range();
    l[2].type = TB_LIGHT_RECT;
    l[2].position = a.position;
    skgl_area_light_axes(&a, &l[2].half_u, &l[2].half_v);
    l[2].strata = 16;
    for (t = 0; t < 3 && !bad; t++) bad = tb_reference_trace_exact(ref, &view, NULL, &l[t], NULL, g_vis[t], NULL) != 0;
    tb_reference_destroy(ref);
    return bad ? -1 : 0;
}

int main(int argc, char **argv)
{
    tb_scene scene;
    esx_scene sc;
    esx_data_header h;
    char err[512];
    tb_gl_context *c;
    FILE *f;
    int t, bad = 0;
    if (argc != 2) { fprintf(stderr, "usage: es_dump OUT\n"); return 2; }
    tb_scene_init(&scene);
    if (tb_scene_build_ground_boxes(&scene) != 0 || trace_reference(&scene) != 0) {
        fprintf(stderr, "es_dump: scene or reference failed\n");
        return 1;
    }
    sc.pos = scene.positions;
    sc.nrm = scene.normals;
    sc.idx = scene.indices;
    sc.vertices = (int)scene.vertex_count;
    sc.indices = (int)scene.index_count;
    sc.bounds = scene.bounds;
    c = tb_gl_context_create(TB_GL_OSMESA, err, sizeof err);
    if (!c) { fprintf(stderr, "es_dump: %s\n", err); return 1; }
    if (esx_begin(&g_run, (esx_getproc)tb_gl_context_getproc(c), &sc, 0) != 0) {
        fprintf(stderr, "es_dump: %s\n", g_run.log);
        return 1;
    }
    while (!esx_step(&g_run)) {}
    for (t = 0; t < ESX_TECHS; t++)
        if (g_run.result[t] != SK_OK) {
            fprintf(stderr, "es_dump: %s: %s\n", esx_techs[t].name, g_run.why[t]);
            bad = 1;
        }
    esx_end(&g_run);
    tb_gl_context_destroy(c);
    memset(&h, 0, sizeof h);
    h.magic = ESX_MAGIC;
    h.vertices = scene.vertex_count;
    h.indices = scene.index_count;
    h.techs = ESX_TECHS;
    h.w = ESX_W;
    h.h = ESX_H;
    memcpy(h.bounds, &scene.bounds, sizeof h.bounds);
    f = fopen(argv[1], "wb");
    if (!f) { fprintf(stderr, "es_dump: cannot write %s\n", argv[1]); return 1; }
    fwrite(&h, sizeof h, 1, f);
    fwrite(scene.positions, 12, scene.vertex_count, f);
    fwrite(scene.normals, 12, scene.vertex_count, f);
    fwrite(scene.indices, 4, scene.index_count, f);
    fwrite(g_run.mask, 1, sizeof g_run.mask, f);
    fwrite(g_vis, 1, sizeof g_vis, f);
    if (fclose(f) != 0) bad = 1;
    tb_scene_free(&scene);
    return bad;
}
