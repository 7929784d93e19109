/* Help from the option tables: `semquad CMD --help` (every option, its
 * default and unit, an example) and `semquad help` (every command). */
#include "cli.h"

#include <stdio.h>
#include <string.h>

#define HELP_COLUMN 28
#define LINE_WIDTH 80

/* "-o, --output FILE" or "    --order Q" into buf. */
static void option_words(const sq_cli_opt *o, char *buf, size_t n)
{
    char s[8] = "    ";
    if (o->short_name) snprintf(s, sizeof s, "-%c, ", o->short_name);
    snprintf(buf, n, "%s--%s%s%s", s, o->name, o->value ? " " : "", o->value ? o->value : "");
}

/* text from column col (the cursor there) to LINE_WIDTH, wrapped at
 * spaces onto lines indented by col. */
static void wrapped(const char *text, int col)
{
    int at = col;
    for (const char *p = text; *p;) {
        int len = (int)strcspn(p, " ");
        if (at > col && at + 1 + len > LINE_WIDTH) at = printf("\n%*s", col, "") - 1;
        at += printf("%s%.*s", at > col ? " " : "", len, p);
        p += len + (p[len] == ' ');
    }
    putchar('\n');
}

void sq_cli_usage(const sq_cli_command *c)
{
    printf("usage: semquad %s FILE [options]\n\n", c->name);
    wrapped(c->summary, 0);
    printf("\noptions:\n");
    for (const sq_cli_opt *o = c->opts; o->name; o++) {
        char words[96], def[256];
        option_words(o, words, sizeof words);
        if ((int)strlen(words) > HELP_COLUMN - 3)
            printf("  %s\n%*s", words, HELP_COLUMN, "");
        else
            printf("  %-*s ", HELP_COLUMN - 3, words);
        wrapped(o->help, HELP_COLUMN);
        if (o->alias_of) continue;
        snprintf(def, sizeof def, "(default: %s%s%s)", o->def ? o->def : "none",
                 o->unit ? "; unit: " : "", o->unit ? o->unit : "");
        printf("%*s", HELP_COLUMN, "");
        wrapped(def, HELP_COLUMN);
    }
    printf("  %-*s %s\n\nexample:\n  %s\n", HELP_COLUMN - 3, "-h, --help", "this text",
           c->example);
}

/* "  mesh FILE [-o FILE] [--order Q] ..." wrapped at LINE_WIDTH, the
 * shared options and the deprecated spellings left out. */
static void command_line(const sq_cli_command *c)
{
    int col = printf("  %s FILE", c->name), indent = (int)strlen(c->name) + 3;
    for (const sq_cli_opt *o = c->opts; o->name; o++) {
        if (o->shared || o->alias_of) continue;
        char word[96];
        if (o->short_name)
            snprintf(word, sizeof word, "[-%c %s]", o->short_name, o->value);
        else
            snprintf(word, sizeof word, "[--%s%s%s]", o->name, o->value ? " " : "",
                     o->value ? o->value : "");
        if (col + 1 + (int)strlen(word) > LINE_WIDTH) col = printf("\n%*s", indent, "") - 1;
        col += printf(" %s", word);
    }
    putchar('\n');
}

void sq_cli_overview(void)
{
    printf("semquad %s - block-structured high-order quad meshes of planar CAD faces\n\n"
           "usage: semquad COMMAND FILE [options]\n"
           "       semquad COMMAND --help   every option of COMMAND, its default and unit\n\n"
           "commands:\n",
           sq_version());
    for (const sq_cli_command *const *c = sq_cli_commands(); *c; c++) {
        command_line(*c);
        printf("%*s", 6, "");
        wrapped((*c)->summary, 6);
    }
    fputs("  help [COMMAND]       this text, or the options of COMMAND\n"
          "  --version            the version\n"
          "\n"
          "FILE is STEP (.step/.stp), IGES (.iges/.igs) or BREP (.brep/.brp); lengths stay in\n"
          "the file's unit. An option's value is the next word or follows '='; -- ends them.\n"
          "Every command reading a face also takes:\n"
          "  --face N             the face (default: the only planar face, else face 0)\n"
          "  --heal-tolerance T   heal gaps, unshared vertices and small edges within T (file\n"
          "                       unit) instead of the file's own tolerance (docs/healing.md)\n"
          "  --no-heal            take the faces as read\n"
          "  -q, --quiet          print nothing but errors\n"
          "Outputs are written to regular files only (a directory, a device or a FIFO is\n"
          "refused) or, as -, to standard output; mesh without -o writes STEM.msh here.\n"
          "\n"
          "exit status: 0 ok, 1 internal error, 2 usage, 3 bad input file, 4 unsupported\n"
          "geometry, 5 invalid singularity pattern, 6 no valid layout, 7 output not written,\n"
          "8 mesh written but its quality below --min-quality, 9 --periodic edges that do not\n"
          "match.\n",
          stdout);
}
