/*
** The two containers of a CFF table (Adobe Technical Note #5176), read
** and written (render/fontfile/sfnt.h):
**   INDEX  count (2 bytes); when count > 0 an offset size (1 to 4) and
**          count + 1 offsets, 1-based from the byte before the data, then
**          the items back to back;
**   DICT   operands (integers in 1, 2, 3 or 5 bytes, reals as nibbles)
**          each run ended by an operator (a byte 0 to 21, 12 escaping a
**          second one);
** and the FDSelect of a CID-keyed font (formats 0 and 3).
** Reading checks that an INDEX ends inside the table and that an item's
** two offsets are in order and inside the data; a DICT's operands stop at
** 48 and its numbers at its end.
*/
#include <string.h>

#include "sfnt.h"

static size_t
read_off(const unsigned char *p, unsigned size)
{
    size_t v = 0;
    unsigned i;
    for (i = 0; i < size; i++)
        v = v << 8 | p[i];
    return v;
}

int
cf__cff_index_read(cf__ff_t *f, const unsigned char *t, size_t tlen,
                   size_t pos, const char *what, cf__cff_index_t *ix)
{
    size_t last;
    memset(ix, 0, sizeof *ix);
    ix->t = t;
    ix->tlen = tlen;
    ix->what = what;
    if (!cf__ff_fits(pos, 2, tlen))
        return cf__ff_fail(f, "CFF %s INDEX at %zu lies past the table's "
                           "end", what, cf__ff_at(f, t) + pos);
    ix->count = cf__ff_u16(t + pos);
    if (ix->count == 0) {
        ix->end = pos + 2;
        return 0;
    }
    if (!cf__ff_fits(pos, 3, tlen) || t[pos + 2] < 1 || t[pos + 2] > 4)
        return cf__ff_fail(f, "CFF %s INDEX at %zu: no offset size of 1 to "
                           "4 bytes", what, cf__ff_at(f, t) + pos);
    ix->off_size = t[pos + 2];
    ix->offsets = pos + 3;
    if (!cf__ff_fits(ix->offsets, (ix->count + 1) * ix->off_size, tlen))
        return cf__ff_fail(f, "CFF %s INDEX at %zu: its %zu offsets run "
                           "past the table's end", what,
                           cf__ff_at(f, t) + pos, ix->count + 1);
    ix->data = ix->offsets + (ix->count + 1) * ix->off_size;
    last = read_off(t + ix->offsets + ix->count * ix->off_size,
                    ix->off_size);
    if (last < 1 || !cf__ff_fits(ix->data, last - 1, tlen))
        return cf__ff_fail(f, "CFF %s INDEX at %zu runs past the table's "
                           "end", what, cf__ff_at(f, t) + pos);
    ix->end = ix->data + last - 1;
    return 0;
}

int
cf__cff_index_item(cf__ff_t *f, const cf__cff_index_t *ix, size_t i,
                   size_t *pos, size_t *len)
{
    size_t a, b;
    if (i >= ix->count)
        return cf__ff_fail(f, "CFF %s INDEX: item %zu of %zu", ix->what, i,
                           ix->count);
    a = read_off(ix->t + ix->offsets + i * ix->off_size, ix->off_size);
    b = read_off(ix->t + ix->offsets + (i + 1) * ix->off_size,
                 ix->off_size);
    if (a < 1 || b < a || ix->data + b - 1 > ix->end)
        return cf__ff_fail(f, "CFF %s INDEX at %zu: item %zu has offsets "
                           "%zu to %zu, out of order or past its end",
                           ix->what, cf__ff_at(f, ix->t) + ix->offsets - 3,
                           i, a, b);
    *pos = ix->data + a - 1;
    *len = b - a;
    return 0;
}

/* v as an offset of size bytes, big-endian, at o. */
static void
put_off(unsigned char *o, size_t v, unsigned size)
{
    unsigned i;
    for (i = 0; i < size; i++)
        o[i] = (unsigned char)(v >> (8 * (size - 1 - i)));
}

int
cf__cff_index_write(cf__buf_t *b, size_t count, cf__cff_item_fn item,
                    void *ctx)
{
    unsigned char head[3], *o, *d;
    size_t i, total = 0, off = 1;
    unsigned size;
    if (count > 0xffff)
        return 1;
    cf__ff_put16(head, (unsigned)count);
    if (count == 0)
        return cf__buf_append(b, head, 2) ? -1 : 0;
    for (i = 0; i < count; i++) {
        const unsigned char *p;
        size_t n;
        item(ctx, i, &p, &n);
        total += n;
    }
    if (total >= 0xffffffffu)
        return 1;
    size = total + 1 <= 0xff ? 1 : total + 1 <= 0xffff ? 2 :
           total + 1 <= 0xffffff ? 3 : 4;
    head[2] = (unsigned char)size;
    /* the INDEX's size known, its offsets and data are written in place
    ** (thousands of items for a font's subroutines, most of them stubs) */
    if (cf__buf_append(b, head, 3) != 0
        || (o = cf__buf_extend(b, (count + 1) * size + total)) == NULL)
        return -1;
    d = o + (count + 1) * size;
    put_off(o, off, size);
    for (i = 0; i < count; i++) {
        const unsigned char *p;
        size_t n;
        item(ctx, i, &p, &n);
        off += n;
        put_off(o + (i + 1) * size, off, size);
        if (n > 0)
            memcpy(d, p, n);
        d += n;
    }
    return 0;
}

int
cf__cff_dict_next(cf__ff_t *f, const unsigned char *p, size_t len,
                  size_t *pos, cf__cff_op_t *op, const char *what)
{
    size_t i = *pos;
    if (i >= len)
        return 0;
    op->nargs = 0;
    op->start = i;
    while (i < len) {
        unsigned b0 = p[i];
        double v = 0;
        size_t need;
        if (b0 <= 21) {
            if (b0 == 12) {
                if (i + 1 >= len)
                    break;
                op->op = 1200 + p[i + 1];
                i += 2;
            } else {
                op->op = b0;
                i++;
            }
            op->end = i;
            *pos = i;
            return 1;
        }
        need = b0 == 28 ? 3 : b0 == 29 ? 5 : b0 >= 247 && b0 <= 254 ? 2 :
               b0 >= 32 && b0 <= 246 ? 1 : b0 == 30 ? 1 : 0;
        if (need == 0)
            return cf__ff_fail(f, "CFF %s DICT at %zu: byte %u is no "
                               "operand or operator", what,
                               cf__ff_at(f, p) + i, b0), -1;
        if (i + need > len)
            break;
        if (b0 == 28)
            v = cf__ff_s16(p + i + 1);
        else if (b0 == 29)
            v = (int32_t)cf__ff_u32(p + i + 1);
        else if (b0 >= 247 && b0 <= 250)
            v = ((double)b0 - 247) * 256.0 + p[i + 1] + 108;
        else if (b0 >= 251 && b0 <= 254)
            v = -((double)b0 - 251) * 256.0 - p[i + 1] - 108;
        else if (b0 != 30)
            v = (double)b0 - 139;
        i += need;
        if (b0 == 30) {   /* a real: nibbles up to 0xf */
            while (i < len && (p[i] & 0x0f) != 0x0f &&
                   (p[i] & 0xf0) != 0xf0)
                i++;
            if (i >= len)
                break;
            i++;
        }
        if (op->nargs >= CF__CFF_MAX_ARGS)
            return cf__ff_fail(f, "CFF %s DICT at %zu: more than %d "
                               "operands", what, cf__ff_at(f, p) + i,
                               CF__CFF_MAX_ARGS), -1;
        op->args[op->nargs++] = v;
    }
    return cf__ff_fail(f, "CFF %s DICT at %zu ends inside an entry", what,
                       cf__ff_at(f, p) + op->start), -1;
}

int
cf__cff_put_int5(cf__buf_t *b, int32_t v)
{
    unsigned char o[5];
    o[0] = 29;
    cf__ff_put32(o + 1, (uint32_t)v);
    return cf__buf_append(b, o, 5);
}

int
cf__cff_put_op(cf__buf_t *b, unsigned op)
{
    unsigned char o[2];
    if (op >= 1200) {
        o[0] = 12;
        o[1] = (unsigned char)(op - 1200);
        return cf__buf_append(b, o, 2);
    }
    o[0] = (unsigned char)op;
    return cf__buf_append(b, o, 1);
}

int
cf__cff_fdselect(const unsigned char *t, size_t tlen, size_t at,
                 unsigned gid, unsigned *fd)
{
    size_t n, lo, hi;
    if (!cf__ff_fits(at, 1, tlen))
        return 1;
    if (t[at] == 0) {
        if (!cf__ff_fits(at + 1, (size_t)gid + 1, tlen))
            return 1;
        *fd = t[at + 1 + gid];
        return 0;
    }
    if (t[at] != 3)
        return 3;
    if (!cf__ff_fits(at, 3, tlen))
        return 1;
    n = cf__ff_u16(t + at + 1);
    if (n == 0 || !cf__ff_fits(at + 3, 3 * n + 2, tlen))
        return 1;
    if (gid < cf__ff_u16(t + at + 3) || gid >= cf__ff_u16(t + at + 3 + 3 * n))
        return 2;
    lo = 0;
    hi = n - 1;   /* the range lo..hi holds gid: first(lo) <= gid */
    while (lo < hi) {
        size_t mid = lo + (hi - lo + 1) / 2;
        if (cf__ff_u16(t + at + 3 + 3 * mid) <= gid)
            lo = mid;
        else
            hi = mid - 1;
    }
    *fd = t[at + 3 + 3 * lo + 2];
    return 0;
}
