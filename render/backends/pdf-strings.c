/*
** PDF strings (render/backends/pdf-strings.h).
*/
#include <string.h>

#include "pdf-strings.h"

static int
put(cf__buf_t *b, const char *s)
{
    return cf__buf_append(b, s, strlen(s));
}

int
cf__pdf_put_string(cf__buf_t *b, const char *s)
{
    int r = put(b, "(");
    for (; *s != '\0' && !r; s++) {
        unsigned char c = (unsigned char)*s;
        char t[4];
        size_t n = 0;
        if (c == '(' || c == ')' || c == '\\') {
            t[n++] = '\\';
            t[n++] = (char)c;
        } else if (c < 32 || c > 126) {
            t[n++] = '\\';
            t[n++] = (char)('0' + (c >> 6));
            t[n++] = (char)('0' + ((c >> 3) & 7));
            t[n++] = (char)('0' + (c & 7));
        } else {
            t[n++] = (char)c;
        }
        r = cf__buf_append(b, t, n);
    }
    return r || put(b, ")") ? -1 : 0;
}

/* Code point at s (advancing it; before end), U+FFFD for a byte that
** starts no valid UTF-8 sequence. */
static unsigned
next_cp(const unsigned char **s, const unsigned char *end)
{
    const unsigned char *p = *s;
    unsigned c = p[0], n = c < 0x80 ? 0 : c >= 0xf0 && c < 0xf5 ? 3
                                     : c >= 0xe0 ? 2 : c >= 0xc2 ? 1 : 9;
    if (n == 9 || (size_t)(end - p) <= n) {
        (*s)++;
        return c < 0x80 ? c : 0xfffd;
    }
    c = n == 0 ? c : c & (0x3fu >> n);
    for (unsigned i = 1; i <= n; i++) {
        if ((p[i] & 0xc0) != 0x80) {
            *s = p + 1;
            return 0xfffd;
        }
        c = (c << 6) | (p[i] & 0x3fu);
    }
    *s = p + n + 1;
    return c;
}

/* u as four upper-case hex digits at h. */
static void
hex_unit(char *h, unsigned u)
{
    static const char digits[] = "0123456789ABCDEF";
    for (int k = 3; k >= 0; k--, u >>= 4)
        h[k] = digits[u & 0xfu];
}

int
cf__pdf_put_utf16(cf__buf_t *out, const char *text, size_t n)
{
    const unsigned char *s = (const unsigned char *)text, *end = s + n;
    char hex[64];   /* up to 8 units, flushed before the next would not
                       fit */
    size_t k = 0;
    while (s < end) {
        unsigned c = next_cp(&s, end);
        if (k + 8 > sizeof hex) {
            if (cf__buf_append(out, hex, k) != 0)
                return -1;
            k = 0;
        }
        if (c >= 0x10000) {
            c -= 0x10000;
            hex_unit(hex + k, 0xd800 + (c >> 10));
            hex_unit(hex + k + 4, 0xdc00 + (c & 0x3ff));
            k += 8;
        } else {
            hex_unit(hex + k, c);
            k += 4;
        }
    }
    return cf__buf_append(out, hex, k) != 0 ? -1 : 0;
}

int
cf__pdf_put_text(cf__buf_t *out, const char *a, const char *b)
{
    const char *parts[3] = { a, b != NULL && b[0] != '\0' ? " " : "",
                             b != NULL ? b : "" };
    int r = put(out, "<FEFF");
    for (int k = 0; k < 3 && r == 0; k++)
        r = cf__pdf_put_utf16(out, parts[k], strlen(parts[k]));
    return r || put(out, ">") ? -1 : 0;
}
