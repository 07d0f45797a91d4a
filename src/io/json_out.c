/* JSON documents built whole or not at all (json_out.h). */
#include "io/json_out.h"

#include <math.h>
#include <stdlib.h>

/* x in 15 significant digits where they read back to x exactly, else in
 * 17, which always do. cJSON's own printing settles for 15 whenever they
 * come within an ulp, so about one number in nine would not read back. */
static void exact_digits(char out[32], double x)
{
    if (x == 0) { /* and -0 */
        snprintf(out, 32, "0");
        return;
    }
    snprintf(out, 32, "%.15g", x);
    if (strtod(out, NULL) != x)
        snprintf(out, 32, "%.17g", x);
}

cJSON *ic_json_out_number(json_out *j, double x)
{
    cJSON *item = NULL;
    if (isfinite(x)) {
        char text[32];
        exact_digits(text, x);
        item = cJSON_CreateRaw(text);
    } else {
        item = cJSON_CreateNull();
    }
    if (!item)
        j->failed = 1;
    return item;
}

cJSON *ic_json_out_vector(json_out *j, const double *v, int n)
{
    cJSON *a = cJSON_CreateArray();
    if (!a)
        j->failed = 1;
    for (int i = 0; a && i < n; i++)
        ic_json_out_append(j, a, ic_json_out_number(j, v[i]));
    return a;
}

void ic_json_out_add(json_out *j, cJSON *obj, const char *key, cJSON *item)
{
    if (!obj || !item || !cJSON_AddItemToObject(obj, key, item)) {
        j->failed = 1;
        cJSON_Delete(item);
    }
}

void ic_json_out_append(json_out *j, cJSON *array, cJSON *item)
{
    if (!array || !item || !cJSON_AddItemToArray(array, item)) {
        j->failed = 1;
        cJSON_Delete(item);
    }
}

ic_status ic_json_out_write(FILE *f, cJSON *doc, const json_out *j, const char *what, ic_error *err)
{
    char *text = doc && !j->failed ? cJSON_Print(doc) : NULL;
    cJSON_Delete(doc);
    if (!text)
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory building the %s output", what);
    const int written = fputs(text, f) >= 0 && fputc('\n', f) != EOF;
    free(text);
    if (!written || ferror(f))
        return ic_error_set(err, IC_ERR_IO, 0, "writing the %s output failed", what);
    return IC_OK;
}
