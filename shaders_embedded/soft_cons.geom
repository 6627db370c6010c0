/* PVSM step 2: conservative rasterisation after Hasselgren et al. (GPU
   Gems 2, ch. 42, second algorithm): every edge is pushed out by the
   semi-diagonal of a texel, so each texel the triangle touches gets a
   fragment; the fragment stage clips the overfill at the corners with the
   triangle's bounding box grown by half a texel. Depth is the triangle's
   own plane, extended; the fragment stage also gets the original edges,
   so that it can tell the triangle's own texels from the grown border.
   Triangles crossing the light's plane (w <= 0) are passed through
   unchanged. skgl_conservative = 0: plain rasterisation.
   A caster program's varyings (SKGL_CASTER_VARYINGS) reach each emitted
   vertex through skgl_caster_varyings(b, s, k) (defined after this source,
   its inputs indexed by constants only): s the corner's barycentric weights
   on the original vertices, extrapolated from its NDC position (what a
   noperspective varying interpolates linearly in the window), b the same
   weighted by 1/w so that the rasteriser's perspective-correct
   interpolation (the corner is emitted at w = 1 / sum(b / w)) gives the
   values the original triangle would have there (smooth and centroid
   varyings); k the vertex whose value a flat varying takes: the grown
   triangle's three corners all take the last vertex's, GL's default
   provoking vertex (the only one in GLSL ES), a triangle passed through
   keeps each vertex's own. */
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
uniform vec2 skgl_texel;          /* 2 / resolution: one texel in NDC */
uniform int skgl_conservative;
flat out vec4 skgl_box;           /* window-space box of the fragments kept */
flat out vec3 skgl_edge[3];       /* the original edges in window space: inside when dot(xy, e) <= z */
#ifdef SKGL_CASTER_VARYINGS
void skgl_caster_varyings(vec3 b, vec3 s, int k);
#endif
void main()
{
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position, c2 = gl_in[2].gl_Position;
    /* outputs are undefined after EmitVertex: every vertex sets them all */
    vec4 box = vec4(-1e30, -1e30, 1e30, 1e30);
    vec3 edge[3] = vec3[3](vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, 1.0));
    if (skgl_conservative == 0 || min(c0.w, min(c1.w, c2.w)) <= 1e-6) {
        for (int i = 0; i < 3; i++) {
            skgl_box = box;
            skgl_edge = edge;
#ifdef SKGL_CASTER_VARYINGS
            vec3 u = vec3(i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0);
            skgl_caster_varyings(u, u, i);
#endif
            gl_Position = gl_in[i].gl_Position;
            EmitVertex();
        }
        EndPrimitive();
        return;
    }
    vec3 p[3] = vec3[3](c0.xyz / c0.w, c1.xyz / c1.w, c2.xyz / c2.w);
    float area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (area == 0.0) return;
    bool swapped = area < 0.0;
    if (swapped) { vec3 t = p[1]; p[1] = p[2]; p[2] = t; area = -area; }
    vec2 h = 0.5 * skgl_texel;
    /* depth plane z = A x + B y + C through the three vertices */
    vec2 e1 = p[1].xy - p[0].xy, e2 = p[2].xy - p[0].xy;
    float dz1 = p[1].z - p[0].z, dz2 = p[2].z - p[0].z;
    float A = (dz1 * e2.y - dz2 * e1.y) / area, B = (e1.x * dz2 - e2.x * dz1) / area;
    /* offset edge lines n.x = d, n the outward normal of edge i -> i+1 */
    vec2 n[3]; float dist[3];
    vec2 vp = 1.0 / skgl_texel;   /* NDC -> window: (x + 1) * res / 2 */
    for (int i = 0; i < 3; i++) {
        vec2 e = p[(i + 1) % 3].xy - p[i].xy;
        n[i] = vec2(e.y, -e.x);
        dist[i] = dot(n[i], p[i].xy);
        /* n.x <= d in NDC is (n / vp).w <= d + n.x + n.y in window space */
        edge[i] = vec3(n[i] / vp, dist[i] + n[i].x + n[i].y);
        dist[i] += abs(n[i].x) * h.x + abs(n[i].y) * h.y;
    }
    vec2 lo = min(p[0].xy, min(p[1].xy, p[2].xy)) - h, hi = max(p[0].xy, max(p[1].xy, p[2].xy)) + h;
    box = vec4((lo + 1.0) * vp, (hi + 1.0) * vp);
    for (int i = 0; i < 3; i++) {
        int j = (i + 2) % 3;      /* the edge ending at vertex i */
        float det = n[j].x * n[i].y - n[j].y * n[i].x;
        vec2 q = abs(det) > 1e-12 * dot(n[i], n[i]) * dot(n[j], n[j])
                     ? vec2(dist[j] * n[i].y - dist[i] * n[j].y, n[j].x * dist[i] - n[i].x * dist[j]) / det
                     : p[i].xy + normalize(n[i]) * length(h);
        q = clamp(q, lo - 2.0 * (hi - lo), hi + 2.0 * (hi - lo));
        float z = p[0].z + A * (q.x - p[0].x) + B * (q.y - p[0].y);
        skgl_box = box;
        skgl_edge = edge;
#ifdef SKGL_CASTER_VARYINGS
        vec2 d0 = q - p[0].xy, d1 = p[1].xy - p[0].xy, d2 = p[2].xy - p[0].xy;
        vec3 b = vec3(0.0, (d0.x * d2.y - d0.y * d2.x) / area, (d1.x * d0.y - d1.y * d0.x) / area);
        b.x = 1.0 - b.y - b.z;
        if (swapped) b = b.xzy;
        vec3 bw = b / vec3(c0.w, c1.w, c2.w);
        float s = bw.x + bw.y + bw.z;
        float W = s > 1e-20 ? 1.0 / s : 1.0;
        skgl_caster_varyings(s > 1e-20 ? bw * W : b, b, 2);
        gl_Position = vec4(q * W, z * W, W);
#else
        gl_Position = vec4(q, z, 1.0);
#endif
        EmitVertex();
    }
    EndPrimitive();
}
