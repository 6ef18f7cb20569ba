#!/usr/bin/env python3
"""A seed of the fontfile fuzz target from a subset the subsetter made.

Usage: fontfile-seed.py ORIGINAL INDEX SUBSET OUT GID...

SUBSET is the program cf__fontfile_subset wrote for face INDEX of the font
file ORIGINAL.  A TrueType subset is a font file as it is; a CFF one (a
bare CID-keyed CFF) is wrapped back into an OpenType file with the
original's head, hhea, OS/2, post and name, a maxp of its glyph count and
the original's first metrics as hmtx.  OUT is the target's input: face 0,
the count and the GIDs (2 bytes each, little-endian: for a CFF seed, glyph
ids of the subset, below its glyph count), then the font.
"""
import struct
import sys


def tables(data, index):
    at = 0
    if data[:4] == b'ttcf':
        at = struct.unpack('>I', data[12 + 4 * index:16 + 4 * index])[0]
    n = struct.unpack('>H', data[at + 4:at + 6])[0]
    out = {}
    for i in range(n):
        tag, _, off, length = struct.unpack(
            '>4sIII', data[at + 12 + 16 * i:at + 28 + 16 * i])
        out[tag] = data[off:off + length]
    return out


def cff_count(cff):
    """The number of charstrings of a CFF written by the subsetter."""
    # the Top DICT ends "29 <CharStrings> 17 29 <FDArray> 12 36"
    pos = cff[2]
    for _ in range(3):   # Name, Top DICT, String INDEXes
        count = struct.unpack('>H', cff[pos:pos + 2])[0]
        size = cff[pos + 2]
        last = int.from_bytes(cff[pos + 3 + count * size:
                                  pos + 3 + (count + 1) * size], 'big')
        if _ == 1:
            top = cff[pos + 3 + (count + 1) * size:
                      pos + 3 + (count + 1) * size + last - 1]
        pos = pos + 3 + (count + 1) * size + last - 1
    assert top[-13] == 29 and top[-8:-6] == bytes([17, 29])
    cs = struct.unpack('>i', top[-12:-8])[0]
    return struct.unpack('>H', cff[cs:cs + 2])[0]


def sfnt(tabs):
    tags = sorted(tabs)
    head = struct.pack('>IHHHH', 0x4F54544F, len(tags), 0, 0, 0)
    off = 12 + 16 * len(tags)
    recs, body = b'', b''
    for t in tags:
        d = tabs[t] + b'\0' * (-len(tabs[t]) % 4)
        recs += struct.pack('>4sIII', t, 0, off, len(tabs[t]))
        body += d
        off += len(d)
    return head + recs + body


def main():
    orig, index, subset, out = sys.argv[1:5]
    gids = [int(g) for g in sys.argv[5:]]
    with open(orig, 'rb') as f:
        src = tables(f.read(), int(index))
    with open(subset, 'rb') as f:
        font = f.read()
    if font[:4] != b'\0\1\0\0':
        n = cff_count(font)
        nhm = min(n, struct.unpack('>H', src[b'hhea'][34:36])[0])
        hhea = src[b'hhea'][:34] + struct.pack('>H', nhm)
        tabs = {b'CFF ': font, b'head': src[b'head'], b'hhea': hhea,
                b'maxp': struct.pack('>IH', 0x5000, n),
                b'hmtx': src[b'hmtx'][:4 * nhm] + b'\0' * (2 * (n - nhm))}
        for t in (b'OS/2', b'post', b'name'):
            if t in src:
                tabs[t] = src[t]
        font = sfnt(tabs)
    with open(out, 'wb') as f:
        f.write(bytes([0, len(gids)]) + b''.join(struct.pack('<H', g)
                                                 for g in gids) + font)


if __name__ == '__main__':
    main()
