/* The interactive page as a file (docs/plots.md, "The interactive page"):
 * what it holds, read back without a browser (tests/browser/ opens it in
 * one). A title made to close the page's script elements must not: every
 * "</script" in the file closes one of its own elements; the trace element
 * holds ic_trace_write_json's document, each '<' written \u003c; the scene
 * element is JSON with the title, the names, the region and the meshes. */
#include <cjson/cJSON.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "harness.h"
#include "intercurve.h"
#include "intercurve/plot.h"
#include "plot/web_assets.h"

static const char HOSTILE[] = "Viviani </script><script>alert(1)</script> <!-- & </SCRIPT x";

/* The file's text (free it), or NULL. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    const long n = ftell(f);
    rewind(f);
    char *text = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (text && fread(text, 1, (size_t)n, f) != (size_t)n) {
        free(text);
        text = NULL;
    }
    if (text)
        text[n] = 0;
    fclose(f);
    return text;
}

static int count_ci(const char *text, const char *what)
{
    int n = 0;
    const size_t m = strlen(what);
    for (const char *p = text; *p; p++)
        n += strncasecmp(p, what, m) == 0;
    return n;
}

/* The text of the element that starts with `open` (up to its "</script>"),
 * as a new string; NULL when there is none. */
static char *element(const char *page, const char *open)
{
    const char *a = strstr(page, open);
    const char *b = a ? strstr(a + strlen(open), "</script>") : NULL;
    if (!b)
        return NULL;
    a += strlen(open);
    char *out = malloc((size_t)(b - a) + 1);
    memcpy(out, a, (size_t)(b - a));
    out[b - a] = 0;
    return out;
}

/* s with every \u003c made '<' again (in place; the writer puts no other). */
static void unescape_lt(char *s)
{
    char *w = s;
    for (const char *r = s; *r;)
        if (strncmp(r, "\\u003c", 6) == 0)
            *w++ = '<', r += 6;
        else
            *w++ = *r++;
    *w = 0;
}

/* What ic_trace_write_json writes for the trace (free it). */
static char *trace_document(const ic_trace_result *res, ic_pair *pair)
{
    char *buf = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&buf, &n);
    ic_error err;
    if (!REQUIRE(f && ic_trace_write_json(f, res, pair, &err) == IC_OK, "trace JSON"))
        return NULL;
    fclose(f);
    return buf;
}

static void check_scene(const char *scene_json, const ic_plot_scene *scene)
{
    cJSON *doc = cJSON_Parse(scene_json);
    if (!REQUIRE(doc != NULL, "the scene element is not JSON"))
        return;
    const cJSON *title = cJSON_GetObjectItem(doc, "title");
    CHECK(cJSON_IsString(title) && strcmp(title->valuestring, HOSTILE) == 0,
          "the title read back: %s", cJSON_IsString(title) ? title->valuestring : "(none)");
    const cJSON *names = cJSON_GetObjectItem(doc, "names");
    CHECK(cJSON_GetArraySize(names) == 2 &&
              strcmp(cJSON_GetArrayItem(names, 0)->valuestring, scene->names[0]) == 0,
          "the surfaces' names");
    const cJSON *meshes = cJSON_GetObjectItem(doc, "meshes");
    CHECK(cJSON_GetArraySize(meshes) == 2, "two meshes");
    for (int s = 0; s < cJSON_GetArraySize(meshes); s++) {
        const cJSON *pos = cJSON_GetObjectItem(cJSON_GetArrayItem(meshes, s), "positions");
        const int n = cJSON_GetArraySize(pos);
        CHECK(n > 0 && n % 9 == 0, "mesh %d: %d coordinates, not whole triangles", s, n);
    }
    const cJSON *box = cJSON_GetObjectItem(doc, "box");
    for (int k = 0; k < 3; k++)
        for (int e = 0; e < 2; e++)
            CHECK(cJSON_GetArrayItem(cJSON_GetArrayItem(box, k), e)->valuedouble == scene->box[k][e],
                  "the region's side %d, %d is the problem's box", k, e);
    cJSON_Delete(doc);
}

static void check_page(const char *path, const ic_plot_scene *scene, ic_pair *pair)
{
    char *page = slurp(path);
    if (!REQUIRE(page != NULL, "read %s", path))
        return;
    /* every closing tag closes one of the page's 7 script elements */
    CHECK(count_ci(page, "</script") == 7, "%d </script in the page",
          count_ci(page, "</script"));
    CHECK(strstr(page, HOSTILE) == NULL, "the title is in the page unescaped");
    CHECK(strstr(page, "<title>Viviani &lt;/script&gt;&lt;script&gt;alert(1)") != NULL,
          "the title element escapes the title");
    char *trace = element(page, "<script type=\"application/json\" id=\"ic-trace\">");
    char *want = trace_document(scene->trace, pair);
    if (REQUIRE(trace && want, "the trace element")) {
        unescape_lt(trace);
        CHECK(strcmp(trace, want) == 0, "the trace element is not ic_trace_write_json's document");
    }
    char *scene_json = element(page, "<script type=\"application/json\" id=\"ic-scene\">");
    if (REQUIRE(scene_json != NULL, "the scene element"))
        check_scene(scene_json, scene);
    free(scene_json);
    free(trace);
    free(want);
    free(page);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: test_plot_html SOURCE_DIR TMPDIR\n");
        return 2;
    }
    char path[1024], out[1024];
    snprintf(path, sizeof path, "%s/examples/viviani-implicit.json", argv[1]);
    snprintf(out, sizeof out, "%s/page.html", argv[2]);
    ic_problem *problem = NULL;
    ic_pair *pair = NULL;
    ic_trace_result *res = NULL;
    ic_error err;
    ic_trace_options opt;
    ic_trace_defaults(&opt);
    if (REQUIRE(ic_problem_load(&problem, path, &err) == IC_OK, "%s: %s", path, err.message) &&
        REQUIRE(ic_pair_new(&pair, ic_problem_surface(problem, 0), ic_problem_surface(problem, 1),
                            &err) == IC_OK,
                "pair: %s", err.message) &&
        REQUIRE((opt.has_box = ic_problem_box(problem, opt.box), ic_trace(&res, pair, &opt, &err)) ==
                    IC_OK,
                "trace: %s", err.message)) {
        ic_plot_scene scene;
        ic_plot_scene_of_problem(&scene, problem, res);
        scene.title = HOSTILE;
        const ic_status st = ic_plot_write(out, &scene, NULL, &err);
        if (!ic_web_have_three) { /* built without web/node_modules */
            CHECK(st == IC_ERR_UNABLE && strstr(err.message, "npm ci"),
                  "without three.js: %s", err.message);
        } else if (REQUIRE(st == IC_OK, "the page: %s", err.message)) {
            check_page(out, &scene, pair);
            snprintf(out, sizeof out, "%s/no/such/dir/page.html", argv[2]);
            CHECK(ic_plot_write(out, &scene, NULL, &err) == IC_ERR_IO, "unwritable: %s",
                  err.message);
        }
    }
    ic_trace_result_free(res);
    ic_pair_free(pair);
    ic_problem_free(problem);
    return harness_finish("test_plot_html");
}
