/* ic_write_file_atomic, called directly: a new file, a replaced one (its
 * mode kept), a writer that fails (the old file intact), a link, a
 * dangling link, a directory, a missing directory, devices; and never a
 * temporary left behind (docs/output-formats.md, "How files are written"). */
#define _XOPEN_SOURCE 700 /* mkdtemp, symlink, readlink */

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "harness.h"
#include "intercurve.h"

/* What the test writer does: print `text`, then fail with `fail` or not. */
typedef struct {
    const char *text;
    ic_status fail;
} script;

static ic_status scripted(FILE *f, void *user, ic_error *err)
{
    const script *s = user;
    fputs(s->text, f);
    if (s->fail != IC_OK)
        return ic_error_set(err, s->fail, 0, "the writer gave up");
    return IC_OK;
}

/* The file's whole content (at most 255 bytes) or "" if unreadable. */
static const char *content(const char *path)
{
    static char buf[256];
    FILE *f = fopen(path, "r");
    const size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    buf[n] = '\0';
    if (f)
        fclose(f);
    return buf;
}

/* The number of names in dir (a temporary left behind adds one). */
static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

static void test_regular(const char *dir)
{
    char path[512];
    snprintf(path, sizeof path, "%s/out.json", dir);
    ic_error err;
    script ok = {"{\"a\": 1}\n", IC_OK};
    CHECK(ic_write_file_atomic(path, scripted, &ok, &err) == IC_OK &&
              strcmp(content(path), ok.text) == 0 && entries(dir) == 1,
          "a new file: written whole, nothing else in the directory (%s)", err.message);
    struct stat st;
    CHECK(stat(path, &st) == 0 && (st.st_mode & 0777) == 0644,
          "a new file: 0666 less the umask 022");
    CHECK(chmod(path, 0600) == 0, "chmod");
    script other = {"second\n", IC_OK};
    CHECK(ic_write_file_atomic(path, scripted, &other, &err) == IC_OK &&
              strcmp(content(path), "second\n") == 0 && stat(path, &st) == 0 &&
              (st.st_mode & 0777) == 0600 && entries(dir) == 1,
          "a replaced file: the new text, its mode 0600 kept, no temporary (%s)", err.message);
    script failing = {"half a docu", IC_ERR_INVALID};
    ic_error_clear(&err);
    CHECK(ic_write_file_atomic(path, scripted, &failing, &err) == IC_ERR_INVALID &&
              strcmp(err.message, "the writer gave up") == 0 &&
              strcmp(content(path), "second\n") == 0 && entries(dir) == 1,
          "a writer that fails: its status and message, the old file intact, no temporary");
    script no_memory = {"", IC_ERR_NOMEM};
    CHECK(ic_write_file_atomic(path, scripted, &no_memory, &err) == IC_ERR_NOMEM &&
              strcmp(content(path), "second\n") == 0,
          "a writer out of memory: IC_ERR_NOMEM, the old file intact");
    unlink(path);
}

static void test_links(const char *dir)
{
    char file[512], link[512], dangling[512], target[512];
    snprintf(file, sizeof file, "%s/file.txt", dir);
    snprintf(link, sizeof link, "%s/link.txt", dir);
    snprintf(dangling, sizeof dangling, "%s/dangling.txt", dir);
    FILE *f = fopen(file, "w");
    if (f)
        fclose(f);
    ic_error err;
    script ok = {"through the link\n", IC_OK};
    const int made = symlink("file.txt", link) == 0 && symlink("nothing.txt", dangling) == 0;
    CHECK(made, "links made");
    if (!made)
        return;
    const ssize_t n = readlink(link, target, sizeof target - 1);
    CHECK(ic_write_file_atomic(link, scripted, &ok, &err) == IC_OK && n > 0 &&
              strcmp(content(file), ok.text) == 0 && readlink(link, target, sizeof target) == n &&
              entries(dir) == 3,
          "a link to a file: the link stays, the file it names is written (%s)", err.message);
    CHECK(ic_write_file_atomic(dangling, scripted, &ok, &err) == IC_ERR_IO &&
              strstr(err.message, "cannot write") && strstr(err.message, "does not exist") &&
              access(dangling, F_OK) != 0 && entries(dir) == 3,
          "a dangling link: refused, nothing created (%s)", err.message);
    unlink(file);
    unlink(link);
    unlink(dangling);
}

static void test_refused(const char *dir)
{
    char path[512];
    ic_error err;
    script ok = {"text\n", IC_OK};
    snprintf(path, sizeof path, "%s/no/such/dir/out.json", dir);
    CHECK(ic_write_file_atomic(path, scripted, &ok, &err) == IC_ERR_IO &&
              strstr(err.message, "cannot write") && strstr(err.message, path) &&
              strstr(err.message, "No such file"),
          "a missing directory: IC_ERR_IO with the path and the reason (%s)", err.message);
    CHECK(ic_write_file_atomic(dir, scripted, &ok, &err) == IC_ERR_IO &&
              strstr(err.message, "Is a directory"),
          "a directory: refused (%s)", err.message);
    if (access("/dev/full", W_OK) == 0) {
        CHECK(ic_write_file_atomic("/dev/null", scripted, &ok, &err) == IC_OK,
              "/dev/null: written in place (%s)", err.message);
        CHECK(ic_write_file_atomic("/dev/full", scripted, &ok, &err) == IC_ERR_IO &&
                  strstr(err.message, "No space left on device"),
              "/dev/full: the system's reason (%s)", err.message);
    }
    CHECK(entries(dir) == 0, "nothing left in the directory");
}

int main(void)
{
    umask(022);
    char dir[] = "/tmp/ic_atomic_XXXXXX";
    if (!mkdtemp(dir)) {
        CHECK(0, "a temporary directory");
        return harness_finish("test_write_atomic");
    }
    test_regular(dir);
    test_links(dir);
    test_refused(dir);
    rmdir(dir);
    return harness_finish("test_write_atomic");
}
