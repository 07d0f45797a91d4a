/* Output files written safely (safe_file.h): a temporary beside a regular
 * target and a rename, or a device written in place. */
/* realpath is XSI in glibc's headers */
#define _XOPEN_SOURCE 700

#include "common/args.h"
#include "json/safe_file.h"

#include "intercurve/writers.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

struct ic_safe_file {
    int fd;
    char *name;   /* the path as given, for messages */
    char *target; /* what the temporary replaces */
    char *tmp;    /* the temporary we created; NULL when writing in place */
};

/* Room kept for the hidden temporary's name: "." + base + ".XXXXXX" must stay
 * within NAME_MAX (255) bytes on common file systems. */
enum { TMP_BASE_MAX = 200, TMP_TRIES = 100 };

static ic_status io_error(ic_error *err, const char *name, int e)
{
    return ic_error_set(err, IC_ERR_IO, 0, "cannot write %s: %s", name, strerror(e));
}

static ic_status nomem(ic_error *err, const char *name)
{
    return ic_error_set(err, IC_ERR_NOMEM, 0, "cannot write %s: out of memory", name);
}

static char *copy_string(const char *s)
{
    const size_t n = strlen(s) + 1;
    char *c = malloc(n);
    return c ? memcpy(c, s, n) : NULL;
}

/* Frees sf, first removing the temporary if it is still there. */
static void release(ic_safe_file *sf)
{
    if (sf->fd >= 0)
        close(sf->fd);
    if (sf->tmp)
        unlink(sf->tmp);
    free(sf->name);
    free(sf->target);
    free(sf->tmp);
    free(sf);
}

/* Six characters for the temporary's name. A guess only costs a retry (the
 * file is created with O_EXCL), so the clock, the process and the attempt,
 * mixed by splitmix64, are random enough. */
static void random_suffix(char out[7], unsigned attempt)
{
    static const char chars[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    uint64_t x = (uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^ ((uint64_t)getpid() << 20) ^
                 ((uint64_t)attempt * 0x9E3779B97F4A7C15u);
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9u;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBu;
    x ^= x >> 31;
    for (int i = 0; i < 6; i++, x /= 62)
        out[i] = chars[x % 62];
    out[6] = '\0';
}

/* "DIR/.BASE." for the target "DIR/BASE", the base cut to TMP_BASE_MAX bytes;
 * NULL with errno set when the target names no file (ends in '/'). */
static char *temp_prefix(const char *target)
{
    const char *slash = strrchr(target, '/');
    const char *base = slash ? slash + 1 : target;
    const size_t dirlen = (size_t)(base - target);
    size_t baselen = strlen(base);
    if (baselen == 0) {
        errno = EISDIR;
        return NULL;
    }
    if (baselen > TMP_BASE_MAX)
        baselen = TMP_BASE_MAX;
    char *p = malloc(dirlen + baselen + 3);
    if (!p) {
        errno = ENOMEM;
        return NULL;
    }
    memcpy(p, target, dirlen);
    p[dirlen] = '.';
    memcpy(p + dirlen + 1, base, baselen);
    memcpy(p + dirlen + 1 + baselen, ".", 2);
    return p;
}

/* Creates sf->tmp beside sf->target. O_EXCL never follows a link planted at
 * the name and never opens a file someone else made, so a user's own files
 * (FILE.tmp or any other) are never touched. mode < 0: a new file, 0666 less
 * the umask like fopen; else the permission bits of the file replaced. Not
 * mkstemp: its 0600 would need the umask, and reading that (umask() sets it)
 * races with other threads creating files. */
static ic_status create_temp(ic_safe_file *sf, int mode, ic_error *err)
{
    char *prefix = temp_prefix(sf->target);
    if (!prefix)
        return errno == ENOMEM ? nomem(err, sf->name) : io_error(err, sf->name, errno);
    const size_t len = strlen(prefix) + 7;
    sf->tmp = malloc(len);
    int e = ENOMEM;
    for (unsigned k = 0; sf->tmp && k < TMP_TRIES && sf->fd < 0; k++) {
        char suffix[7];
        random_suffix(suffix, k);
        snprintf(sf->tmp, len, "%s%s", prefix, suffix);
        sf->fd = open(sf->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        e = errno;
        if (sf->fd < 0 && e != EEXIST)
            break;
    }
    free(prefix);
    if (sf->fd < 0) {
        free(sf->tmp);
        sf->tmp = NULL; /* not ours: never unlinked */
        return e == ENOMEM ? nomem(err, sf->name) : io_error(err, sf->name, e);
    }
    if (mode >= 0 && fchmod(sf->fd, (mode_t)mode) != 0)
        return io_error(err, sf->name, errno);
    return IC_OK;
}

/* A device, FIFO or socket (or a link to one): opened where it is, never
 * created, truncated or replaced. */
static ic_status open_in_place(ic_safe_file *sf, ic_error *err)
{
    sf->fd = open(sf->name, O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (sf->fd < 0)
        return io_error(err, sf->name, errno);
    /* it was swapped for a regular file since we looked: writing it in place
     * would leave the old tail behind */
    struct stat st;
    if (fstat(sf->fd, &st) != 0 || S_ISREG(st.st_mode))
        return ic_error_set(err, IC_ERR_IO, 0, "cannot write %s: it changed while being opened",
                            sf->name);
    return IC_OK;
}

/* A symbolic link: the link stays. A regular file behind it is replaced
 * beside itself (its resolved path); anything else is written through. */
static ic_status open_through_link(ic_safe_file *sf, ic_error *err)
{
    struct stat st;
    if (stat(sf->name, &st) != 0) {
        if (errno != ENOENT)
            return io_error(err, sf->name, errno);
        /* a dangling link: what it points at is not created through it */
        return ic_error_set(err, IC_ERR_IO, 0,
                            "cannot write %s: a symbolic link to a file that does not exist",
                            sf->name);
    }
    if (S_ISDIR(st.st_mode))
        return io_error(err, sf->name, EISDIR);
    if (!S_ISREG(st.st_mode))
        return open_in_place(sf, err);
    free(sf->target);
    sf->target = realpath(sf->name, NULL);
    if (!sf->target)
        return io_error(err, sf->name, errno);
    return create_temp(sf, (int)(st.st_mode & 0777), err);
}

/* Chooses how to write, by what `path` is now. */
static ic_status open_by_kind(ic_safe_file *sf, ic_error *err)
{
    struct stat st;
    if (lstat(sf->name, &st) != 0)
        return errno == ENOENT ? create_temp(sf, -1, err) : io_error(err, sf->name, errno);
    if (S_ISLNK(st.st_mode))
        return open_through_link(sf, err);
    if (S_ISDIR(st.st_mode))
        return io_error(err, sf->name, EISDIR);
    if (S_ISREG(st.st_mode))
        return create_temp(sf, (int)(st.st_mode & 0777), err);
    return open_in_place(sf, err);
}

ic_status ic_safe_open(ic_safe_file **out, const char *path, ic_error *err)
{
    *out = NULL;
    if (!path || !path[0])
        return ic_error_set(err, IC_ERR_INVALID, 0, "cannot write a file without a name");
    const size_t len = strlen(path);
    if (path[len - 1] == '/')
        return ic_error_set(err, IC_ERR_INVALID, 0, "cannot write %s: it names a directory", path);
    ic_safe_file *sf = calloc(1, sizeof *sf);
    if (!sf)
        return nomem(err, path);
    sf->fd = -1;
    sf->name = copy_string(path);
    sf->target = copy_string(path);
    if (!sf->name || !sf->target) {
        release(sf);
        return nomem(err, path);
    }
    const ic_status st = open_by_kind(sf, err);
    if (st != IC_OK) {
        release(sf);
        return st;
    }
    *out = sf;
    return IC_OK;
}

ic_status ic_safe_write(ic_safe_file *sf, const void *data, size_t n, ic_error *err)
{
    const char *p = data;
    while (n > 0) {
        const ssize_t w = write(sf->fd, p, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return io_error(err, sf->name, w < 0 ? errno : EIO);
        p += w;
        n -= (size_t)w;
    }
    return IC_OK;
}

ic_status ic_safe_commit(ic_safe_file *sf, ic_error *err)
{
    ic_status st = IC_OK;
    /* synced before the rename, so that a crash leaves the old file or the
     * whole new one, never an empty one */
    if (sf->tmp && fsync(sf->fd) != 0)
        st = io_error(err, sf->name, errno);
    const int closed = close(sf->fd);
    sf->fd = -1;
    if (st == IC_OK && closed != 0)
        st = io_error(err, sf->name, errno);
    if (st == IC_OK && sf->tmp && rename(sf->tmp, sf->target) != 0)
        st = io_error(err, sf->name, errno);
    if (st == IC_OK) {
        free(sf->tmp); /* renamed: nothing left to remove */
        sf->tmp = NULL;
    }
    release(sf);
    return st;
}

void ic_safe_abort(ic_safe_file *sf)
{
    if (sf)
        release(sf);
}

ic_status ic_write_file_atomic(const char *path, ic_file_writer writer, void *user,
                               ic_error *err)
{
    IC_ARG_NOT_NULL(path, "path");
    IC_ARG_NOT_NULL(writer, "writer");
    char *text = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&text, &len);
    if (!mem)
        return nomem(err, path);
    ic_status st = writer(mem, user, err);
    /* a memory stream fails only for want of memory */
    if (st == IC_ERR_IO || (st == IC_OK && ferror(mem)))
        st = nomem(err, path);
    if (fclose(mem) != 0 && st == IC_OK)
        st = nomem(err, path);
    if (st != IC_OK) { /* the writer's own reason; the target is left as it was */
        free(text);
        return st;
    }
    ic_safe_file *sf;
    st = ic_safe_open(&sf, path, err);
    if (st == IC_OK)
        st = ic_safe_write(sf, text, len, err);
    if (st == IC_OK)
        st = ic_safe_commit(sf, err);
    else
        ic_safe_abort(sf);
    free(text);
    return st;
}
