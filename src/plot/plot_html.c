/*
 * The interactive page (docs/plots.md, "The interactive page"): one HTML
 * file holding three.js and the page's own scripts as text (web/, compiled
 * in: plot/web_assets.h), the scene's data and the trace document as JSON.
 * The bootstrap script (web/boot.js) turns the texts into modules.
 */
#include "plot_html.h"

#include "intercurve.h"
#include "intercurve/writers.h"
#include "plot/web_assets.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

/* 1 when text holds "</script" in any case: it would end its element. */
static int closes_script(const char *text, size_t n)
{
    static const char TAG[] = "</script";
    const size_t m = sizeof TAG - 1;
    for (size_t i = 0; i + m <= n; i++)
        if (text[i] == '<') {
            size_t k = 1;
            while (k < m && tolower((unsigned char)text[i + k]) == TAG[k])
                k++;
            if (k == m)
                return 1;
        }
    return 0;
}

/* Text for people inside HTML: & < > " escaped. */
static void html_text(FILE *f, const char *s)
{
    for (; *s; s++)
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*s, f);
        }
}

static void raw_script(FILE *f, const char *id, ic_web_part part)
{
    fprintf(f, "<script type=\"text/plain\" id=\"%s\">", id);
    fwrite(ic_web_texts[part].text, 1, ic_web_texts[part].size, f);
    fputs("</script>\n", f);
}

/* The trace document as ic_trace_write_json prints it, each '<' (only ever
 * inside a string) written \u003c so that no title or name can end the
 * script element; JSON.parse reads it back the same. */
static ic_status write_trace(FILE *f, const ic_plot_scene *scene, ic_error *err)
{
    if (!scene->trace) {
        fputs("null\n", f);
        return IC_OK;
    }
    ic_pair *pair = NULL;
    ic_status st = ic_pair_new(&pair, scene->surfaces[0],
                               scene->nsurfaces == 2 ? scene->surfaces[1] : NULL, err);
    if (st != IC_OK)
        return st;
    char *buf = NULL;
    size_t n = 0;
    FILE *mem = open_memstream(&buf, &n);
    if (!mem) {
        ic_pair_free(pair);
        return ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory writing the page's trace");
    }
    st = ic_trace_write_json(mem, scene->trace, pair, err);
    if (fclose(mem) != 0 && st == IC_OK)
        st = ic_error_set(err, IC_ERR_NOMEM, 0, "out of memory writing the page's trace");
    ic_pair_free(pair);
    for (size_t i = 0; st == IC_OK && i < n; i++)
        if (buf[i] == '<')
            fputs("\\u003c", f);
        else
            fputc(buf[i], f);
    free(buf);
    return st;
}

static ic_status write_page(FILE *f, void *user, ic_error *err)
{
    const void *const *args = user;
    const ic_plot_scene *scene = args[0];
    const ic_plot_options *opt = args[1];
    const char *title = scene->title && *scene->title ? scene->title : "intercurve";
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta name=\"generator\" content=\"intercurve " IC_VERSION "\">\n<title>",
          f);
    html_text(f, title);
    fputs("</title>\n<style>\n", f);
    fwrite(ic_web_texts[IC_WEB_PAGE_CSS].text, 1, ic_web_texts[IC_WEB_PAGE_CSS].size, f);
    fputs("</style>\n</head>\n<body>\n", f);
    fwrite(ic_web_texts[IC_WEB_PAGE_BODY].text, 1, ic_web_texts[IC_WEB_PAGE_BODY].size, f);
    raw_script(f, "ic-three-core", IC_WEB_THREE_CORE);
    raw_script(f, "ic-three-module", IC_WEB_THREE_MODULE);
    raw_script(f, "ic-orbit-controls", IC_WEB_ORBIT_CONTROLS);
    raw_script(f, "ic-page", IC_WEB_PAGE_JS);
    fputs("<script type=\"application/json\" id=\"ic-scene\">", f);
    ic_status st = ic_html_write_scene(f, scene, opt, err);
    fputs("</script>\n<script type=\"application/json\" id=\"ic-trace\">", f);
    if (st == IC_OK)
        st = write_trace(f, scene, err);
    fputs("</script>\n<script>\n", f);
    fwrite(ic_web_texts[IC_WEB_BOOT_JS].text, 1, ic_web_texts[IC_WEB_BOOT_JS].size, f);
    fputs("</script>\n</body>\n</html>\n", f);
    return st;
}

ic_status ic_plot_write_html(const char *path, const ic_plot_scene *scene,
                             const ic_plot_options *opt, ic_error *err)
{
    if (!ic_web_have_three)
        return ic_error_set(err, IC_ERR_UNABLE, 0,
                            "cannot write %s: this intercurve was built without three.js; run "
                            "'npm ci' in the source's web/ directory and build again "
                            "(docs/plots.md)",
                            path);
    for (int p = 0; p < IC_WEB_NTEXTS; p++)
        if (p != IC_WEB_PAGE_CSS && p != IC_WEB_PAGE_BODY &&
            closes_script(ic_web_texts[p].text, ic_web_texts[p].size))
            return ic_error_set(err, IC_ERR_UNABLE, 0,
                                "cannot write %s: a script of the page holds \"</script\"", path);
    const void *args[2] = {scene, opt};
    return ic_write_file_atomic(path, write_page, args, err);
}
