"""Reads a static quantized-mesh tile set (riverworld tiles --format quantized-mesh) with a
decoder written from the quantized-mesh-1.0 spec alone (CesiumGS/quantized-mesh), and checks
every tile: header, zig-zag vertices inside 0..32767, high-water-mark indices inside the vertex
count, counter-clockwise triangles, edge lists on their sides, the extensions layer.json names,
and that side-sharing tiles of a level agree along most of their borders."""
import json, os, struct, sys

def decode(b):
    min_h, max_h = struct.unpack_from('<2f', b, 24)
    (n,) = struct.unpack_from('<I', b, 88)
    at = 92
    def stream():
        nonlocal at
        out, v = [], 0
        for (z,) in struct.iter_unpack('<H', b[at:at + 2 * n]):
            v += (z >> 1) ^ -(z & 1)
            out.append(v)
        at += 2 * n
        return out
    u, v, h = stream(), stream(), stream()
    wide = n > 65536
    fmt, size = ('<I', 4) if wide else ('<H', 2)
    if at % size:
        at += size - at % size
    (t,) = struct.unpack_from('<I', b, at)
    at += 4
    idx, high = [], 0
    for (c,) in struct.iter_unpack(fmt, b[at:at + 3 * t * size]):
        idx.append(high - c)
        if c == 0:
            high += 1
    at += 3 * t * size
    edges = []
    for _ in range(4):
        (k,) = struct.unpack_from('<I', b, at)
        at += 4
        edges.append([x for (x,) in struct.iter_unpack(fmt, b[at:at + k * size])])
        at += k * size
    ext = {}
    while at < len(b):
        (i, length) = struct.unpack_from('<BI', b, at)
        ext[i] = b[at + 5:at + 5 + length]
        at += 5 + length
    assert at == len(b), 'trailing bytes'
    height = [min_h + x / 32767 * (max_h - min_h) for x in h]
    return dict(u=u, v=v, h=height, step=(max_h - min_h) / 32767, idx=idx, edges=edges, ext=ext)

def check(path, d):
    n = len(d['u'])
    assert all(0 <= c <= 32767 for c in d['u'] + d['v']), path
    assert d['idx'] and all(0 <= i < n for i in d['idx']), path
    for k in range(0, len(d['idx']), 3):
        a, b, c = d['idx'][k:k + 3]
        area = (d['u'][b] - d['u'][a]) * (d['v'][c] - d['v'][a]) - (d['u'][c] - d['u'][a]) * (d['v'][b] - d['v'][a])
        assert area > 0, f'{path}: triangle {k // 3} is not counter-clockwise'
    for side, (coord, want) in zip(d['edges'], [('u', 0), ('v', 0), ('u', 32767), ('v', 32767)]):
        assert side and all(d[coord][i] == want for i in side), f'{path}: edge list off its side'
    assert set(d['ext']) == {1, 2, 4} or set(d['ext']) == {1, 2}, f'{path}: extensions {sorted(d["ext"])}'
    assert len(d['ext'][1]) == 2 * n and len(d['ext'][2]) in (1, 65536), path

def main(root):
    layer = json.load(open(os.path.join(root, 'layer.json')))
    assert layer['format'] == 'quantized-mesh-1.0' and layer['scheme'] == 'tms'
    tiles, agree, pairs = {}, 0, 0
    for z in range(layer['maxzoom'] + 1):
        for x in range(2 << z):
            for y in range(1 << z):
                path = os.path.join(root, str(z), str(x), f'{y}.terrain')
                d = decode(open(path, 'rb').read())
                check(path, d)
                tiles[z, x, y] = d
    for (z, x, y), d in tiles.items():
        e = tiles[z, (x + 1) % (2 << z), y]
        a = [d['h'][i] for i in d['edges'][2]]
        b = [e['h'][i] for i in e['edges'][0]]
        pairs += 1
        agree += len(a) == len(b) and all(abs(p - q) <= d['step'] + e['step'] + 1e-3 for p, q in zip(a, b))
    assert agree >= 0.95 * pairs, f'{agree} of {pairs} east borders agree'
    print(f'{len(tiles)} quantized-mesh tiles read; {agree} of {pairs} shared east borders agree')

main(sys.argv[1])
