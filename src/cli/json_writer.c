/* JSON output helpers for the command. */
#include "cli.h"

#include <math.h>
#include <stdlib.h>

cJSON *ic_json_number_or_null(double x)
{
    return isfinite(x) ? cJSON_CreateNumber(x + 0.0) : cJSON_CreateNull(); /* -0 -> 0 */
}

cJSON *ic_json_vector(const double *v, int n)
{
    cJSON *a = cJSON_CreateArray();
    for (int i = 0; a && i < n; i++)
        cJSON_AddItemToArray(a, ic_json_number_or_null(v[i]));
    return a;
}

int ic_json_write(FILE *f, cJSON *doc)
{
    char *text = doc ? cJSON_Print(doc) : NULL;
    cJSON_Delete(doc);
    const int ok = text && fputs(text, f) >= 0 && fputc('\n', f) != EOF;
    free(text);
    return ok ? 0 : -1;
}

int ic_json_print(cJSON *doc)
{
    if (ic_json_write(stdout, doc) != 0 || fflush(stdout) != 0) {
        fprintf(stderr, "intercurve: cannot write the output (out of memory or a write error)\n");
        return -1;
    }
    return 0;
}
