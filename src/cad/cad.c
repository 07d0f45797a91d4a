/* CAD files (cad.h): the dispatcher, which finds a file's format, reads its
 * bytes and hands them to the STEP or IGES reader (cad_readers.h), the only
 * caller of the readers. */
#include "cad.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cad_readers.h"

ic_cad_format ic_cad_sniff(const char *data, size_t len)
{
    static const char MAGIC[] = "ISO-10303-21";
    size_t k = 0;
    while (k < len && (unsigned char)data[k] <= ' ')
        k++;
    if (len - k >= sizeof MAGIC - 1 && memcmp(data + k, MAGIC, sizeof MAGIC - 1) == 0)
        return IC_CAD_STEP;
    /* column 73 of the first record: 'S' */
    const char *nl = memchr(data, '\n', len);
    const size_t first = nl ? (size_t)(nl - data) : len;
    if (first > 72 && data[72] == 'S')
        return IC_CAD_IGES;
    return IC_CAD_ANY;
}

const char *ic_cad_format_name(ic_cad_format format)
{
    return format == IC_CAD_STEP ? "STEP" : format == IC_CAD_IGES ? "IGES" : "CAD";
}

/* The format of the data, checked against the one asked for. */
static ic_status format_of(const char *data, size_t len, ic_cad_format want, ic_cad_format *got,
                           ic_error *err)
{
    *got = ic_cad_sniff(data, len);
    if (*got == IC_CAD_ANY && want == IC_CAD_ANY)
        return ic_error_set(err, IC_ERR_PARSE, 0,
                            "neither a STEP file (it would begin with ISO-10303-21;) nor an IGES "
                            "file (its first record would have S in column 73)");
    if (*got == IC_CAD_ANY)
        return ic_error_set(err, IC_ERR_PARSE, 0, "not %s file (%s)",
                            want == IC_CAD_STEP ? "a STEP" : "an IGES",
                            want == IC_CAD_STEP ? "it does not begin with ISO-10303-21;"
                                                : "its first record has no S in column 73");
    if (want != IC_CAD_ANY && *got != want)
        return ic_error_set(err, IC_ERR_INVALID, 0, "not %s file: it is %s file",
                            want == IC_CAD_STEP ? "a STEP" : "an IGES",
                            *got == IC_CAD_STEP ? "a STEP" : "an IGES");
    return IC_OK;
}

ic_status ic_cad_list_buffer(const char *data, size_t len, ic_cad_format format,
                             ic_cad_surface **list, int *n, ic_cad_info *info, ic_error *err)
{
    *list = NULL;
    *n = 0;
    ic_cad_info scratch;
    if (!info)
        info = &scratch;
    memset(info, 0, sizeof *info);
    ic_cad_format got;
    ic_status st = format_of(data, len, format, &got, err);
    if (st != IC_OK)
        return st;
    info->format = got;
    if (got == IC_CAD_STEP) {
        ic_step_file f;
        if ((st = ic_step_parse(&f, data, len, err)) != IC_OK)
            return st;
        st = ic_step_list(&f, list, n, info, err);
        ic_step_free(&f);
    } else {
        ic_iges_file f;
        if ((st = ic_iges_parse(&f, data, len, err)) != IC_OK)
            return st;
        st = ic_iges_list(&f, list, n, info, err);
        ic_iges_free(&f);
    }
    if (st != IC_OK) {
        ic_cad_list_free(*list, *n);
        *list = NULL;
        *n = 0;
    }
    return st;
}

/* ic_cad_read_buffer, saying whose fault a failure is. */
static ic_status read_buffer(const char *data, size_t len, ic_cad_format format, int entity,
                             ic_cad_surface *out, int *entity_fault, ic_error *err)
{
    memset(out, 0, sizeof *out);
    *entity_fault = 0;
    ic_cad_format got;
    ic_status st = format_of(data, len, format, &got, err);
    if (st != IC_OK)
        return st;
    if (got == IC_CAD_STEP) {
        ic_step_file f;
        if ((st = ic_step_parse(&f, data, len, err)) != IC_OK)
            return st;
        st = ic_step_read(&f, entity, out, err);
        *entity_fault = st != IC_OK;
        ic_step_free(&f);
    } else {
        ic_iges_file f;
        if ((st = ic_iges_parse(&f, data, len, err)) != IC_OK)
            return st;
        st = ic_iges_read(&f, entity, out, err);
        *entity_fault = st != IC_OK;
        ic_iges_free(&f);
    }
    return st;
}

ic_status ic_cad_read_buffer(const char *data, size_t len, ic_cad_format format, int entity,
                             ic_cad_surface *out, ic_error *err)
{
    int entity_fault;
    return read_buffer(data, len, format, entity, out, &entity_fault, err);
}

/* The whole file into a new buffer (*data NULL for an empty file). */
static ic_status slurp(const char *path, char **data, size_t *len, ic_error *err)
{
    *data = NULL;
    *len = 0;
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return ic_error_set(err, IC_ERR_IO, 0, "cannot read %s: %s", path, strerror(errno));
    struct stat info;
    if (fstat(fileno(fp), &info) != 0 || !S_ISREG(info.st_mode)) { /* not a FIFO, a device */
        fclose(fp);
        return ic_error_set(err, IC_ERR_IO, 0, "cannot read %s: not a regular file", path);
    }
    size_t cap = 0;
    ic_status st = IC_OK;
    while (st == IC_OK && *len <= IC_CAD_MAX_FILE) {
        if (*len == cap) { /* up to one byte past the limit, to see a longer file */
            cap = cap ? 2 * cap : 65536;
            if (cap > (size_t)IC_CAD_MAX_FILE + 1)
                cap = (size_t)IC_CAD_MAX_FILE + 1;
            char *grown = realloc(*data, cap);
            if (!grown) {
                st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory reading %s", path);
                break;
            }
            *data = grown;
        }
        const size_t got = fread(*data + *len, 1, cap - *len, fp);
        *len += got;
        if (got == 0)
            break;
    }
    if (st == IC_OK && *len > IC_CAD_MAX_FILE)
        st = ic_error_set(err, IC_ERR_INVALID, 0, "%s is larger than %d bytes, the most read",
                          path, IC_CAD_MAX_FILE);
    if (st == IC_OK && ferror(fp))
        st = ic_error_set(err, IC_ERR_IO, 0, "cannot read %s: a read error", path);
    fclose(fp);
    if (st != IC_OK) {
        free(*data);
        *data = NULL;
    }
    return st;
}

/* Messages of the reader begin with the file's path. */
static ic_status with_path(ic_status st, const char *path, ic_error *err)
{
    if (st != IC_OK && err && st != IC_ERR_IO && strncmp(err->message, path, strlen(path)) != 0) {
        char msg[IC_ERROR_MESSAGE_LEN];
        snprintf(msg, sizeof msg, "%s", err->message);
        ic_error_set(err, st, 0, "%s: %s", path, msg);
    }
    return st;
}

ic_status ic_cad_list(const char *path, ic_cad_format format, ic_cad_surface **list, int *n,
                      ic_cad_info *info, ic_error *err)
{
    char *data;
    size_t len;
    *list = NULL;
    *n = 0;
    ic_status st = slurp(path, &data, &len, err);
    if (st == IC_OK)
        st = ic_cad_list_buffer(data ? data : "", len, format, list, n, info, err);
    free(data);
    return with_path(st, path, err);
}

ic_status ic_cad_read_entity(const char *path, ic_cad_format format, int entity,
                             ic_cad_surface *out, int *entity_fault, ic_error *err)
{
    char *data;
    size_t len;
    memset(out, 0, sizeof *out);
    *entity_fault = 0;
    ic_status st = slurp(path, &data, &len, err);
    if (st == IC_OK)
        st = read_buffer(data ? data : "", len, format, entity, out, entity_fault, err);
    free(data);
    return with_path(st, path, err);
}

ic_status ic_cad_read(const char *path, ic_cad_format format, int entity, ic_cad_surface *out,
                      ic_error *err)
{
    int entity_fault;
    return ic_cad_read_entity(path, format, entity, out, &entity_fault, err);
}
