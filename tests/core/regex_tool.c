/* Reads "PATTERN<TAB>TOPIC" lines on stdin, both hex-encoded (so any byte can be tested), and
 * prints, per line, what ubii_regex_search says:
 * "match", "nomatch", "invalid", "unsupported", "toolarge" or "timeout". Used by
 * regex_agrees_with_javascript.js. */
#include <stdio.h>
#include <string.h>

#include "ubii/topic.h"

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    return -1;
}

/* Decodes hex text in place; false for odd length or a bad digit. */
static int unhex(char *text)
{
    size_t length = strlen(text);
    if (length % 2 != 0) {
        return 0;
    }
    for (size_t i = 0; i < length; i += 2) {
        int high = hex_digit(text[i]);
        int low = hex_digit(text[i + 1]);
        if (high < 0 || low < 0) {
            return 0;
        }
        text[i / 2] = (char)(high * 16 + low);
    }
    text[length / 2] = '\0';
    return 1;
}

int main(void)
{
    static char line[16384];
    while (fgets(line, sizeof line, stdin) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        char *tab = strchr(line, '\t');
        if (tab == NULL) {
            puts("invalid-line");
            continue;
        }
        *tab = '\0';
        if (!unhex(line) || !unhex(tab + 1)) {
            puts("invalid-line");
            continue;
        }
        switch (ubii_regex_search(line, tab + 1)) {
        case UBII_OK:
            puts("match");
            break;
        case UBII_ERR_NOT_FOUND:
            puts("nomatch");
            break;
        case UBII_ERR_UNSUPPORTED:
            puts("unsupported");
            break;
        case UBII_ERR_TOO_LARGE:
            puts("toolarge");
            break;
        case UBII_ERR_TIMEOUT:
            puts("timeout");
            break;
        default:
            puts("invalid");
            break;
        }
    }
    return 0;
}
