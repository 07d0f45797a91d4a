/* The streamed JSON layout (json/json_out.h) against cJSON_Print, the
 * printer the documents used before they were streamed: the same
 * structures built as cJSON trees and written with ic_json_out give the
 * same bytes (empty objects and arrays, objects in arrays in objects,
 * escapes, null, booleans, integers, numbers of 15 and 17 digits). */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "json/json_out.h"
#include "json/json_number.h"

/* what a document writer would write; its tree in *tree */
static void streamed(json_out *j)
{
    static const double v[3] = {0.1, -1.0 / 3, 1e-300};
    ic_json_out_object(j);
    ic_json_out_key(j, "empty object");
    ic_json_out_object(j);
    ic_json_out_end_object(j);
    ic_json_out_key(j, "empty array");
    ic_json_out_array(j);
    ic_json_out_end_array(j);
    ic_json_out_key(j, "list");
    ic_json_out_array(j);
    for (int i = 0; i < 2; i++) {
        ic_json_out_object(j);
        ic_json_out_key(j, "v");
        ic_json_out_vector(j, v, 3);
        ic_json_out_key(j, "inner");
        ic_json_out_array(j);
        ic_json_out_object(j);
        ic_json_out_end_object(j);
        ic_json_out_null(j);
        ic_json_out_vector(j, v, i);
        ic_json_out_end_array(j);
        ic_json_out_end_object(j);
    }
    ic_json_out_end_array(j);
    ic_json_out_key(j, "te\"xt\\");
    ic_json_out_string(j, "tab\t nl\n cr\r bs\b ff\f \x01 \x1f caf\xc3\xa9");
    ic_json_out_key(j, "flags");
    ic_json_out_array(j);
    ic_json_out_bool(j, 1);
    ic_json_out_bool(j, 0);
    ic_json_out_int(j, -42);
    ic_json_out_number(j, NAN);
    ic_json_out_number(j, -0.0);
    ic_json_out_end_array(j);
    ic_json_out_end_object(j);
}

static cJSON *number(double x)
{
    if (!isfinite(x))
        return cJSON_CreateNull();
    char text[IC_JSON_NUMBER_MAX];
    ic_json_number_text(text, x);
    return cJSON_CreateRaw(text);
}

static cJSON *vector(const double *v, int n)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; i < n; i++)
        cJSON_AddItemToArray(a, number(v[i]));
    return a;
}

static cJSON *tree(void)
{
    static const double v[3] = {0.1, -1.0 / 3, 1e-300};
    cJSON *doc = cJSON_CreateObject();
    cJSON_AddItemToObject(doc, "empty object", cJSON_CreateObject());
    cJSON_AddItemToObject(doc, "empty array", cJSON_CreateArray());
    cJSON *list = cJSON_CreateArray();
    for (int i = 0; i < 2; i++) {
        cJSON *o = cJSON_CreateObject();
        cJSON_AddItemToObject(o, "v", vector(v, 3));
        cJSON *inner = cJSON_CreateArray();
        cJSON_AddItemToArray(inner, cJSON_CreateObject());
        cJSON_AddItemToArray(inner, cJSON_CreateNull());
        cJSON_AddItemToArray(inner, vector(v, i));
        cJSON_AddItemToObject(o, "inner", inner);
        cJSON_AddItemToArray(list, o);
    }
    cJSON_AddItemToObject(doc, "list", list);
    cJSON_AddItemToObject(doc, "te\"xt\\",
                          cJSON_CreateString("tab\t nl\n cr\r bs\b ff\f \x01 \x1f caf\xc3\xa9"));
    cJSON *flags = cJSON_CreateArray();
    cJSON_AddItemToArray(flags, cJSON_CreateTrue());
    cJSON_AddItemToArray(flags, cJSON_CreateFalse());
    cJSON_AddItemToArray(flags, cJSON_CreateNumber(-42));
    cJSON_AddItemToArray(flags, number(NAN));
    cJSON_AddItemToArray(flags, number(-0.0));
    cJSON_AddItemToObject(doc, "flags", flags);
    return doc;
}

int main(void)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!REQUIRE(f != NULL, "a memory stream"))
        return harness_finish("json_out");
    json_out *j = malloc(sizeof *j);
    if (!REQUIRE(j != NULL, "the writer's buffer")) {
        fclose(f);
        return harness_finish("json_out");
    }
    ic_json_out_start(j, f);
    streamed(j);
    ic_error err;
    CHECK(ic_json_out_finish(j, "test", &err) == IC_OK, "the document is written");
    fclose(f);
    free(j);
    cJSON *doc = tree();
    char *want = cJSON_Print(doc);
    cJSON_Delete(doc);
    if (REQUIRE(want != NULL && text != NULL, "both texts")) {
        CHECK(len == strlen(want) + 1 && strncmp(text, want, len - 1) == 0 && text[len - 1] == '\n',
              "the streamed text is cJSON_Print's and a newline:\n%s\n---- cJSON_Print:\n%s", text,
              want);
    }
    free(want);
    free(text);
    return harness_finish("json_out");
}
