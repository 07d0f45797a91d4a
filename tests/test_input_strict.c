/* Strict problem files (docs/problem-files.md, "Strictness"): duplicate
 * keys, NUL characters, numbers that are not finite and magnitudes that
 * would overflow are errors naming their JSON path; every bundled example
 * still loads, from a file and from memory without a terminating NUL.
 * usage: test_input_strict SOURCE_DIR */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

/* A problem text (it may hold NUL bytes, hence the explicit length), the
 * status, the error's path and a part of its message. */
typedef struct {
    const char *json;
    size_t len;
    ic_status status;
    const char *path;
    const char *message;
} bad_case;

#define TEXT(s) s, sizeof s - 1
/* two implicit planes: the rest of a valid problem around the fault
 * ("{" OK_SURFACES is 77 characters: line and columns below count on it) */
#define PLANES "{\"type\": \"implicit\", \"f\": \"x\"}, {\"type\": \"implicit\", \"f\": \"y\"}"
#define OK_SURFACES "\"surfaces\": [" PLANES "]"

static const bad_case CASES[] = {
    /* duplicate keys, at every depth */
    {TEXT("{" OK_SURFACES ", " OK_SURFACES "}"), IC_ERR_INVALID, "surfaces", "duplicate key"},
    {TEXT("{\"constants\": {\"R\": 1, \"r\": 2, \"R\": 3}, " OK_SURFACES "}"), IC_ERR_INVALID,
     "constants.R", "duplicate key \"R\""},
    {TEXT("{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x\", \"f\": \"y - 1\"}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].f", "duplicate key"},
    {TEXT("{" OK_SURFACES ", \"title\": {\"a\": [{\"b\": 1, \"b\": 1}]}}"), IC_ERR_INVALID,
     "title.a[0].b", "duplicate key \"b\""},
    {TEXT("[{\"k\": 1, \"k\": 2}]"), IC_ERR_INVALID, "(root)[0].k", "duplicate key"},
    /* NUL characters: escapes and raw bytes, in values and keys */
    {TEXT("{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x\\u0000 + 1\"}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].f", "NUL character (\\u0000) inside a string"},
    {TEXT("{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x\"}, "
          "{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\0 + 1\", \"0\"]}]}"),
     IC_ERR_INVALID, "surfaces[1].xyz[1]", "NUL byte inside a string"},
    {TEXT("{\"title\": \"a\\u0000b\", " OK_SURFACES "}"), IC_ERR_INVALID, "title",
     "NUL character"},
    {TEXT("{\"constants\": {\"R\\u0000x\": 1}, " OK_SURFACES "}"), IC_ERR_INVALID, "constants.R",
     "inside a key"},
    {TEXT("{" OK_SURFACES ",\0 \"title\": \"t\"}"), IC_ERR_INVALID, "(line 1, column 79)",
     "NUL byte outside any string"},
    {TEXT("{" OK_SURFACES "}\0"), IC_ERR_PARSE, "(line 1, column 79)",
     "NUL byte after the JSON document"},
    /* cJSON skips a raw NUL as white space; the column counts it */
    {TEXT("{\0 x}"), IC_ERR_PARSE, "(line 1, column 5)", "invalid JSON"},
    /* an escaped backslash before "u0000" is no NUL: the formula is wrong */
    {TEXT("{\"surfaces\": [{\"type\": \"implicit\", \"f\": \"x\\\\u0000\"}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_PARSE, "surfaces[0].f", "unexpected character"},
    /* text after the document */
    {TEXT("{" OK_SURFACES "} {}"), IC_ERR_PARSE, "(line 1, column 80)",
     "text after the end of the document"},
    /* numbers that are not finite, wherever they are */
    {TEXT("{" OK_SURFACES ", \"box\": [[0, 1], [0, 1e400], [0, 1]]}"), IC_ERR_INVALID,
     "box[1][1]", "not a finite number"},
    {TEXT("{\"constants\": {\"R\": -1e999}, " OK_SURFACES "}"), IC_ERR_INVALID, "constants.R",
     "not a finite number"},
    {TEXT("{\"constants\": {\"R\": \"1e308*10\"}, " OK_SURFACES "}"), IC_ERR_PARSE,
     "constants.R", "not a finite number"},
    {TEXT("{\"constants\": {\"R\": 1e300, \"S\": \"R*R\"}, " OK_SURFACES "}"), IC_ERR_PARSE,
     "constants.S", "not a finite number"},
    {TEXT("{" OK_SURFACES ", \"box\": [[0, 1], [0, 1], [\"-exp(800)\", 1]]}"), IC_ERR_PARSE,
     "box[2][0]", "not a finite number"},
    {TEXT("{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1e400}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].radius", "not a finite number"},
    {TEXT("{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1, \"center\": [0, 0, -1e400]}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].center[2]", "not a finite number"},
    {TEXT("{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", 1e999]}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].xyz[2]", "not a finite number"},
    {TEXT("{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", \"0\"], "
          "\"domain\": [[0, 1], [0, 1e309]]}, {\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].domain[1][1]", "not a finite number"},
    {TEXT("{\"title\": 1e400, " OK_SURFACES "}"), IC_ERR_INVALID, "title",
     "not a finite number"},
    /* finite, but the width or the squares would overflow */
    {TEXT("{" OK_SURFACES ", \"box\": [[-1e308, 1e308], [0, 1], [0, 1]]}"), IC_ERR_INVALID,
     "box[0][0]", "too large"},
    {TEXT("{" OK_SURFACES ", \"box\": [[0, 1], [0, 1], [0, 2e150]]}"), IC_ERR_INVALID,
     "box[2][1]", "too large"},
    {TEXT("{\"surfaces\": [{\"type\": \"parametric\", \"xyz\": [\"u\", \"v\", \"0\"], "
          "\"domain\": [[-1e200, 1e200], [0, 1]]}, {\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].domain[0][0]", "too large"},
    {TEXT("{\"surfaces\": [{\"type\": \"cylinder\", \"form\": \"parametric\", \"radius\": 1, "
          "\"domain\": [[0, 1], [-1.7e308, 1.7e308]]}, {\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].domain[1][0]", "too large"},
    {TEXT("{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1e200}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].radius", "too large"},
    {TEXT("{\"surfaces\": [{\"type\": \"ellipsoid\", \"axes\": [1, 1e-200, 1]}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].axes[1]", "too small"},
    {TEXT("{\"surfaces\": [{\"type\": \"plane\", \"normal\": [1e200, 0, 0]}, "
          "{\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].normal[0]", "too large"},
    {TEXT("{\"surfaces\": [{\"type\": \"torus\", \"major_radius\": 2, \"minor_radius\": 1, "
          "\"center\": [1e151, 0, 0]}, {\"type\": \"implicit\", \"f\": \"y\"}]}"),
     IC_ERR_INVALID, "surfaces[0].center[0]", "too large"},
};

/* Problems at the edge of the rules, which must load. */
static const char *const GOOD[] = {
    "{" OK_SURFACES ", \"box\": [[-1e150, 1e150], [0, 1], [0, 1]]}",
    "{\"constants\": {\"R\": 1e300, \"S\": \"R/1e10\"}, " OK_SURFACES "}",
    "{\"title\": \"a\\\\u0000 is an escaped backslash, then text\", " OK_SURFACES "}",
    "{\"surfaces\": [{\"type\": \"sphere\", \"radius\": 1e-150, \"center\": [1e150, 0, 0]}, "
    "{\"type\": \"implicit\", \"f\": \"y\"}]}",
    "{\"constants\": {\"R\": 1}, \"title\": \"keys in two objects may repeat\", "
    "\"surfaces\": [{\"name\": \"R\", \"type\": \"implicit\", \"f\": \"x - R\"}, "
    "{\"name\": \"S\", \"type\": \"implicit\", \"f\": \"y\"}]}\n \t\r\n",
};

/* Loads from a buffer of exactly len bytes (no NUL after it), so a read
 * past the end would be seen by the sanitizers. */
static ic_status parse_exact(ic_problem **p, const char *json, size_t len, ic_error *err)
{
    char *copy = malloc(len ? len : 1);
    if (!copy)
        return IC_ERR_NOMEM;
    memcpy(copy, json, len);
    ic_status st = ic_problem_parse(p, copy, len, err);
    free(copy);
    return st;
}

static void test_rejected(void)
{
    for (size_t i = 0; i < sizeof CASES / sizeof CASES[0]; i++) {
        const bad_case *c = &CASES[i];
        ic_problem *p = NULL;
        ic_error err;
        ic_status st = parse_exact(&p, c->json, c->len, &err);
        CHECK(st == c->status && p == NULL, "case %zu (%s): status %d, want %d", i, c->path,
              (int)st, (int)c->status);
        CHECK(err.code == c->status, "case %zu: err.code %d", i, (int)err.code);
        CHECK(strcmp(err.path, c->path) == 0, "case %zu: path '%s', want '%s' (%s)", i,
              err.path, c->path, err.message);
        CHECK(strstr(err.message, c->message) != NULL, "case %zu (%s): message '%s' lacks '%s'",
              i, c->path, err.message, c->message);
        ic_problem_free(p);
    }
}

static void test_edges_load(void)
{
    for (size_t i = 0; i < sizeof GOOD / sizeof GOOD[0]; i++) {
        ic_problem *p = NULL;
        ic_error err;
        CHECK(parse_exact(&p, GOOD[i], strlen(GOOD[i]), &err) == IC_OK,
              "edge case %zu must load: %s: %s", i, err.path, err.message);
        ic_problem_free(p);
    }
}

/* Every bundled example, from its file and from memory. */
static void test_examples_load(const char *src)
{
    char dir[1024], file[2048];
    snprintf(dir, sizeof dir, "%s/examples", src);
    DIR *d = opendir(dir);
    CHECK(d != NULL, "cannot open %s", dir);
    if (!d)
        return;
    int loaded = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        const size_t n = strlen(e->d_name);
        if (n < 5 || strcmp(e->d_name + n - 5, ".json") != 0)
            continue;
        snprintf(file, sizeof file, "%s/%s", dir, e->d_name);
        ic_problem *p = NULL;
        ic_error err;
        CHECK(ic_problem_load(&p, file, &err) == IC_OK, "%s: %s: %s", e->d_name, err.path,
              err.message);
        ic_problem_free(p);
        FILE *f = fopen(file, "rb");
        char *buf = malloc(IC_PROBLEM_MAX_FILE);
        const size_t len = f && buf ? fread(buf, 1, IC_PROBLEM_MAX_FILE, f) : 0;
        if (f)
            fclose(f);
        p = NULL;
        CHECK(len > 0 && parse_exact(&p, buf, len, &err) == IC_OK, "%s from memory: %s",
              e->d_name, err.message);
        ic_problem_free(p);
        free(buf);
        loaded++;
    }
    closedir(d);
    CHECK(loaded >= 15, "only %d examples found in %s", loaded, dir);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s SOURCE_DIR\n", argv[0]);
        return 2;
    }
    test_rejected();
    test_edges_load();
    test_examples_load(argv[1]);
    return harness_finish("test_input_strict");
}
