/* The listing of `intercurve surfaces` (api.h): the CAD reader's list of a
 * file's surfaces, written by its listing writer (src/cad/cad_write.c). */
#include "api/api.h"

#include "cad/cad.h"
#include "cad/cad_write.h"

ic_status ic_api_list_surfaces(FILE *f, const char *path, int json, int *read_failed, ic_error *err)
{
    ic_cad_surface *list = NULL;
    int n = 0;
    ic_cad_info info;
    *read_failed = 1;
    ic_status st = ic_cad_list(path, IC_CAD_ANY, &list, &n, &info, err);
    if (st != IC_OK)
        return st;
    *read_failed = 0;
    st = ic_cad_write_list(f, path, &info, list, n, json, err);
    ic_cad_list_free(list, n);
    return st;
}
