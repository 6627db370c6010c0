/* embed: writes the GLSL sources of this folder into shadowkit_gl.h as
   readable C string literals, between the lines
       SKGL_EMBEDDED_SHADERS_BEGIN  and  SKGL_EMBEDDED_SHADERS_END
   (each inside a comment).
     embed --write HEADER FILE...   rewrite HEADER in place
     embed --check HEADER FILE...   exit 1 if HEADER differs from what
                                    --write would produce (make check)
   Each FILE becomes `static const char skgl__src_<name>[]`, <name> being
   the file name with '.' replaced by '_'. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (!f) { perror(path); exit(2); }
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)n + 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n) { fprintf(stderr, "%s: read error\n", path); exit(2); }
    buf[n] = 0;
    fclose(f);
    *len = (size_t)n;
    return buf;
}

/* appends to a growing buffer */
typedef struct { char *p; size_t n, cap; } buf_t;
static void put(buf_t *b, const char *s, size_t n)
{
    if (b->n + n + 1 > b->cap) {
        b->cap = (b->n + n + 1) * 2;
        b->p = (char *)realloc(b->p, b->cap);
        if (!b->p) { fprintf(stderr, "out of memory\n"); exit(2); }
    }
    memcpy(b->p + b->n, s, n);
    b->n += n;
    b->p[b->n] = 0;
}
static void puts_(buf_t *b, const char *s) { put(b, s, strlen(s)); }

static void emit_file(buf_t *b, const char *path)
{
    size_t len, i;
    char *src = slurp(path, &len), name[256];
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    snprintf(name, sizeof name, "%s", base);
    for (i = 0; name[i]; i++) if (name[i] == '.' || name[i] == '-') name[i] = '_';
    puts_(b, "static const char skgl__src_");
    puts_(b, name);
    puts_(b, "[] =\n");
    i = 0;
    while (i < len) {
        puts_(b, "    \"");
        while (i < len && src[i] != '\n') {
            char c = src[i++];
            if (c == '\\' || c == '"') put(b, "\\", 1);
            if (c == '\t') { puts_(b, "    "); continue; }
            put(b, &c, 1);
        }
        puts_(b, "\\n\"\n");
        i++;
    }
    puts_(b, "    ;\n");
    free(src);
}

int main(int argc, char **argv)
{
    size_t hlen;
    char *hdr, *begin, *end;
    buf_t out = {0, 0, 0};
    int i, check;
    if (argc < 4 || (strcmp(argv[1], "--write") && strcmp(argv[1], "--check"))) {
        fprintf(stderr, "usage: embed --write|--check HEADER FILE...\n");
        return 2;
    }
    check = !strcmp(argv[1], "--check");
    hdr = slurp(argv[2], &hlen);
    begin = strstr(hdr, "SKGL_EMBEDDED_SHADERS_BEGIN");
    end = strstr(hdr, "SKGL_EMBEDDED_SHADERS_END");
    if (!begin || !end || end < begin) { fprintf(stderr, "%s: markers not found\n", argv[2]); return 2; }
    begin = strchr(begin, '\n');        /* keep the whole BEGIN line */
    while (end > hdr && end[-1] != '\n') end--;   /* keep the whole END line */
    put(&out, hdr, (size_t)(begin + 1 - hdr));
    for (i = 3; i < argc; i++) emit_file(&out, argv[i]);
    put(&out, end, hlen - (size_t)(end - hdr));
    if (check) {
        if (out.n != hlen || memcmp(out.p, hdr, hlen)) {
            fprintf(stderr, "%s: embedded shaders differ from %s... (run `make shaders`)\n", argv[2], argv[3]);
            return 1;
        }
        return 0;
    } else {
        FILE *f = fopen(argv[2], "wb");
        if (!f || fwrite(out.p, 1, out.n, f) != out.n || fclose(f)) { perror(argv[2]); return 2; }
    }
    free(out.p);
    free(hdr);
    return 0;
}
