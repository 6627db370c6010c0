/* scene_bake.c - a scene file (any format assimp reads) into the flat form
   the web demo embeds: "SKWS", vertex count, index count, the bounds (6
   floats), positions, normals (3 floats each), indices (uint32). Scaled to
   about 20 m across and set on the ground (y = 0), with a ground quad added
   under it so that its shadows have somewhere to fall.
   usage: scene_bake IN OUT   (exit 0 on success) */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tb_scene.h"

#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    tb_scene s;
    FILE *f;
    unsigned magic = 0x53574B53u, nv, ni, i;
    float scale, cx, cz, y0, b[6];
    if (argc != 3) { fprintf(stderr, "usage: scene_bake IN OUT\n"); return 2; }
    tb_scene_init(&s);
    if (tb_scene_load(&s, argv[1]) != 0 || s.vertex_count == 0) {
        fprintf(stderr, "scene_bake: cannot read %s\n", argv[1]);
        return 1;
    }
    {
        float dx = s.bounds.max.x - s.bounds.min.x, dy = s.bounds.max.y - s.bounds.min.y;
        float dz = s.bounds.max.z - s.bounds.min.z, m = dx > dy ? (dx > dz ? dx : dz) : (dy > dz ? dy : dz);
        scale = m > 0.0f ? 14.0f / m : 1.0f;
        cx = 0.5f * (s.bounds.min.x + s.bounds.max.x);
        cz = 0.5f * (s.bounds.min.z + s.bounds.max.z);
        y0 = s.bounds.min.y;
    }
    for (i = 0; i < s.vertex_count; i++) {
        s.positions[3 * i] = (s.positions[3 * i] - cx) * scale;
        s.positions[3 * i + 1] = (s.positions[3 * i + 1] - y0) * scale;
        s.positions[3 * i + 2] = (s.positions[3 * i + 2] - cz) * scale;
    }
    s.bounds.min.x = (s.bounds.min.x - cx) * scale; s.bounds.max.x = (s.bounds.max.x - cx) * scale;
    s.bounds.min.y = 0.0f; s.bounds.max.y = (s.bounds.max.y - y0) * scale;
    s.bounds.min.z = (s.bounds.min.z - cz) * scale; s.bounds.max.z = (s.bounds.max.z - cz) * scale;
    if (tb_scene_add_ground(&s, "ground", 0.0f, 0.0f, 12.0f, 12.0f, 0.0f, 4, 4) < 0) {
        fprintf(stderr, "scene_bake: out of memory\n");
        return 1;
    }
    nv = s.vertex_count;
    ni = s.index_count;
    memcpy(b, &s.bounds, sizeof b);
    f = fopen(argv[2], "wb");
    if (!f) return 1;
    fwrite(&magic, 4, 1, f);
    fwrite(&nv, 4, 1, f);
    fwrite(&ni, 4, 1, f);
    fwrite(b, 4, 6, f);
    fwrite(s.positions, 12, nv, f);
    fwrite(s.normals, 12, nv, f);
    fwrite(s.indices, 4, ni, f);
    if (fclose(f) != 0) return 1;
    printf("scene_bake: %s: %u triangles\n", argv[2], ni / 3);
    tb_scene_free(&s);
    return 0;
}
