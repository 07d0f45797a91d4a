/* The interactive page's pieces, compiled into the library from the file
 * that cmake/embed_web.cmake generates at build time: the page's own CSS,
 * HTML body and scripts (web/), and three.js from web/node_modules, which
 * is there only after `npm ci` in web/ (docs/plots.md, "The interactive
 * page"). */
#ifndef IC_WEB_ASSETS_H
#define IC_WEB_ASSETS_H

#include <stddef.h>

/* In the order of cmake/embed_web.cmake's lists. */
typedef enum {
    IC_WEB_PAGE_CSS,
    IC_WEB_PAGE_BODY,
    IC_WEB_BOOT_JS,
    IC_WEB_PAGE_JS,
    IC_WEB_THREE_CORE,
    IC_WEB_THREE_MODULE,
    IC_WEB_ORBIT_CONTROLS,
    IC_WEB_NTEXTS
} ic_web_part;

typedef struct {
    const char *text; /* NULL where the build did not find the file */
    size_t size;      /* bytes, without the terminating NUL */
} ic_web_text;

extern const ic_web_text ic_web_texts[IC_WEB_NTEXTS];
/* 1 when three.js was found in web/node_modules at build time */
extern const int ic_web_have_three;

#endif
