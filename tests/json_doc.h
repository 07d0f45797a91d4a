/* The writers' JSON documents read back for the tests: a writer's output
 * captured whole, parsed with cJSON, and its values compared exactly with
 * the doubles they came from (every number must round-trip). */
#ifndef IC_TEST_JSON_DOC_H
#define IC_TEST_JSON_DOC_H

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "intercurve.h"

/* Everything writer(f, user, err) writes, as a string (free it), with its
 * status in *st; NULL when the text cannot be had. */
static inline char *doc_text(ic_file_writer writer, void *user, ic_status *st, ic_error *err)
{
    FILE *f = tmpfile();
    if (!f)
        return NULL;
    *st = writer(f, user, err);
    const long len = ftell(f);
    char *text = len >= 0 ? malloc((size_t)len + 1) : NULL;
    rewind(f);
    if (text && fread(text, 1, (size_t)len, f) != (size_t)len) {
        free(text);
        text = NULL;
    }
    if (text)
        text[len] = '\0';
    fclose(f);
    return text;
}

/* The document the writer prints, parsed (cJSON_Delete it); NULL after a
 * failed CHECK when it does not write one whole JSON value and a newline. */
static inline cJSON *doc_parse(ic_file_writer writer, void *user, const char *what)
{
    ic_error err;
    ic_error_clear(&err);
    ic_status st = IC_ERR_IO;
    char *text = doc_text(writer, user, &st, &err);
    CHECK(st == IC_OK && text, "%s: written (%s)", what, err.message);
    const char *end = NULL;
    cJSON *doc = text ? cJSON_ParseWithOpts(text, &end, 0) : NULL;
    CHECK(doc && strcmp(end, "\n") == 0, "%s: one JSON document and a newline", what);
    free(text);
    return doc;
}

/* The item is the number x exactly, or null where x is not finite. */
static inline int doc_number_is(const cJSON *item, double x)
{
    if (!isfinite(x))
        return cJSON_IsNull(item);
    return cJSON_IsNumber(item) && item->valuedouble == x;
}

/* The item is an array of exactly the n numbers v. */
static inline int doc_vector_is(const cJSON *item, const double *v, int n)
{
    if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != n)
        return 0;
    for (int i = 0; i < n; i++)
        if (!doc_number_is(cJSON_GetArrayItem(item, i), v[i]))
            return 0;
    return 1;
}

static inline int doc_string_is(const cJSON *item, const char *s)
{
    return cJSON_IsString(item) && strcmp(item->valuestring, s) == 0;
}

/* The object's keys are exactly `keys` (NULL-terminated), in this order. */
static inline int doc_keys_are(const cJSON *obj, const char *const *keys)
{
    const cJSON *item = obj ? obj->child : NULL;
    for (; *keys; keys++, item = item->next)
        if (!item || strcmp(item->string, *keys) != 0)
            return 0;
    return item == NULL;
}

static inline const cJSON *doc_get(const cJSON *obj, const char *key)
{
    return cJSON_GetObjectItemCaseSensitive(obj, key);
}

#endif
