/* STEP Part 21 (ISO 10303-21) exchange structure: tokens and the table of
 * entity instances, for the CAD reader (cad.h). Values are kept in one
 * array of nodes linked by index; text values point into the file's bytes
 * (which must outlive the table). */
#ifndef IC_STEP_PARSE_H
#define IC_STEP_PARSE_H

#include <stddef.h>
#include <stdint.h>

#include "intercurve/common.h"

/* Most values (numbers, references, lists, ...) in one file, and deepest
 * nesting of lists and typed parameters. */
#define IC_STEP_MAX_VALUES (8 * 1024 * 1024)
#define IC_STEP_MAX_DEPTH 32

typedef enum {
    IC_STEP_NUMBER,  /* integer or real */
    IC_STEP_STRING,  /* 'text' (text, len: between the quotes, '' not undone) */
    IC_STEP_ENUM,    /* .NAME. (text, len: NAME) */
    IC_STEP_REF,     /* #n */
    IC_STEP_NULL,    /* $ */
    IC_STEP_DERIVED, /* * */
    IC_STEP_BINARY,  /* "hex" */
    IC_STEP_LIST,    /* ( ... ): child is the first item, count the items */
    IC_STEP_TYPED    /* NAME( ... ): text, len the name; child its LIST of parameters */
} ic_step_kind;

typedef struct {
    uint8_t kind;
    int32_t next;  /* the next item of the enclosing list, or of a complex instance; -1 */
    int32_t child; /* -1 when none */
    int32_t count;
    union {
        double number;
        int32_t ref;
        struct {
            uint32_t text, len;
        } s;
    } u;
} ic_step_value;

typedef struct {
    int32_t id;
    int32_t part;  /* a TYPED value: the instance's type and parameters; a complex
                      instance has several, linked by next */
    int complex;
} ic_step_instance;

typedef struct {
    const char *text;
    size_t len;
    ic_step_value *values;
    int nvalues, cap_values;
    ic_step_instance *inst; /* sorted by id */
    int ninst, cap_inst;
} ic_step_file;

/* Reads the exchange structure in text[0..len) (not NUL-terminated).
 * IC_ERR_PARSE with the line and what is wrong; *f is then empty. */
ic_status ic_step_parse(ic_step_file *f, const char *text, size_t len, ic_error *err);
void ic_step_free(ic_step_file *f);

/* The instance #id, or NULL. */
const ic_step_instance *ic_step_find(const ic_step_file *f, int id);
/* The TYPED value of the instance's part called `type` (simple: its only
 * part), or -1. */
int ic_step_part(const ic_step_file *f, const ic_step_instance *in, const char *type);
/* Item k (from 0) of a LIST value, or -1. */
int ic_step_item(const ic_step_file *f, int list, int k);
/* Parameter k of a TYPED value, or -1. */
int ic_step_param(const ic_step_file *f, int typed, int k);
/* 1 when the text of value v (TYPED name, ENUM) is `name`. */
int ic_step_is(const ic_step_file *f, int v, const char *name);
/* The text of a value (name, enumeration, string with '' undone) into out. */
void ic_step_text(const ic_step_file *f, int v, char *out, size_t size);
/* The number of v (a NUMBER, or a TYPED measure around one): 0, or -1. */
int ic_step_number(const ic_step_file *f, int v, double *x);

#endif
