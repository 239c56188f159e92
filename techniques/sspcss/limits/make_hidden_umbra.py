#!/usr/bin/env python3
# Writes hidden_umbra.gltf, the scene of the README's "Limits" picture: a back wall facing the
# camera, an overhang whose umbra covers the wall from y = 5 m down to ~2.8 m, and a board in
# front of the wall that hides that umbra (from the loader's default camera) but not the
# penumbra below it. The glTF loader places the camera (frame_bounds) and the light itself.
#   python3 make_hidden_umbra.py hidden_umbra.gltf
import base64, json, struct, sys
BOARD = 3.94  # the board's lower edge, m: the default camera's line of sight to y = 2.78 on the wall
pos, nrm, idx = [], [], []
def quad(p0, p1, p2, p3, n):
    b = len(pos) // 3
    for p in (p0, p1, p2, p3):
        pos.extend(p); nrm.extend(n)
    idx.extend([b, b + 1, b + 2, b, b + 2, b + 3])
def box(lo, hi):
    x0, y0, z0 = lo; x1, y1, z1 = hi
    quad((x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1), (0, 0, 1))    # +z
    quad((x1, y0, z0), (x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (0, 0, -1))   # -z
    quad((x1, y0, z1), (x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (1, 0, 0))    # +x
    quad((x0, y0, z0), (x0, y0, z1), (x0, y1, z1), (x0, y1, z0), (-1, 0, 0))   # -x
    quad((x0, y1, z1), (x1, y1, z1), (x1, y1, z0), (x0, y1, z0), (0, 1, 0))    # +y
    quad((x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1), (0, -1, 0))   # -y
quad((-5, 0, 4), (5, 0, 4), (5, 0, -2), (-5, 0, -2), (0, 1, 0))  # ground
quad((-5, 0, -2), (5, 0, -2), (5, 6, -2), (-5, 6, -2), (0, 0, 1))  # back wall, facing the camera
box((-4.0, 4.9, -2.0), (4.0, 5.1, -1.0))  # overhang: its umbra covers the wall from y = 5 down to ~2.8
box((-1.5, BOARD, 0.9), (1.5, BOARD + 2.0, 1.1))  # board in front: hides that umbra, not the penumbra below
pb = struct.pack(f"<{len(pos)}f", *pos); nb = struct.pack(f"<{len(nrm)}f", *nrm)
ib = struct.pack(f"<{len(idx)}I", *idx)
data = pb + nb + ib
n = len(pos) // 3
gltf = {
    "asset": {"version": "2.0", "generator": "techniques/sspcss/limits/make_hidden_umbra.py"},
    "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "limits"}],
    "meshes": [{"name": "limits", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
    "materials": [{"name": "grey", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.7, 0.7, 1.0]}}],
    "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pb), "target": 34962},
                    {"buffer": 0, "byteOffset": len(pb), "byteLength": len(nb), "target": 34962},
                    {"buffer": 0, "byteOffset": len(pb) + len(nb), "byteLength": len(ib), "target": 34963}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": n, "type": "VEC3",
         "min": [min(pos[0::3]), min(pos[1::3]), min(pos[2::3])], "max": [max(pos[0::3]), max(pos[1::3]), max(pos[2::3])]},
        {"bufferView": 1, "componentType": 5126, "count": n, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5125, "count": len(idx), "type": "SCALAR"}],
}
json.dump(gltf, open(sys.argv[1], "w"), separators=(",", ":"))
