#!/usr/bin/env python3
"""Writes an OBJ+MTL scene (and its SCENE.camera) as one glTF 2.0 file with an embedded buffer:
    scenes/tools/obj_to_gltf.py scenes/cornell/cornell.obj scenes/cornell/cornell.gltf

Each OBJ object (`o`/`g`) becomes a node with a mesh, one primitive per material; each face a
fan of triangles (0 1 2, 0 2 3, ...), which hemirad's glTF loader joins back into the polygon.
Kd is baseColorFactor; Ke becomes emissiveFactor (scaled into [0, 1]) times
KHR_materials_emissive_strength. The camera sidecar becomes a perspective camera node. Only what
hemirad's own scenes use: v, f (vertex indices), o/g, usemtl, mtllib, newmtl, Kd, Ke.
"""
import base64, json, math, os, struct, sys

def read_mtl(path):
    mats, cur = {}, None
    for line in open(path):
        w = line.split()
        if not w or w[0].startswith('#'): continue
        if w[0] == 'newmtl': cur = mats.setdefault(' '.join(w[1:]), {'Kd': [0.0] * 3, 'Ke': [0.0] * 3})
        elif w[0] in ('Kd', 'Ke') and cur is not None:
            v = [float(x) for x in w[1:4]]
            cur[w[0]] = v * 3 if len(v) == 1 else v
    return mats

def read_obj(path):
    verts, objects, mats, obj, mat = [], {}, {}, 'default', None
    for line in open(path):
        w = line.split()
        if not w or w[0].startswith('#'): continue
        if w[0] == 'v': verts.append([float(x) for x in w[1:4]])
        elif w[0] in ('o', 'g'): obj = ' '.join(w[1:])
        elif w[0] == 'usemtl': mat = ' '.join(w[1:])
        elif w[0] == 'mtllib': mats.update(read_mtl(os.path.join(os.path.dirname(path), ' '.join(w[1:]))))
        elif w[0] == 'f':
            idx = [int(t.split('/')[0]) for t in w[1:]]
            face = [verts[i - 1] if i > 0 else verts[len(verts) + i] for i in idx]
            objects.setdefault(obj, {}).setdefault(mat, []).append(face)
    return objects, mats

def camera_node(path):
    cam = {'eye': [0, 0, 1], 'target': [0, 0, 0], 'up': [0, 1, 0], 'fov': [45.0]}
    text = ' '.join(l.split('#')[0] for l in open(path))
    for item in text.split():
        k, v = item.split('=')
        cam[k] = [float(x) for x in v.split(',')]
    sub = lambda a, b: [a[i] - b[i] for i in range(3)]
    cross = lambda a, b: [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
    norm = lambda a: [x / math.sqrt(sum(y * y for y in a)) for x in a]
    fwd = norm(sub(cam['target'], cam['eye']))
    right = norm(cross(fwd, cam['up']))
    up = cross(right, fwd)
    back = [-x for x in fwd]
    matrix = right + [0] + up + [0] + back + [0] + cam['eye'] + [1]  # column-major
    return {'name': 'camera', 'camera': 0, 'matrix': matrix}, math.radians(cam['fov'][0])

def main(obj_path, out_path):
    objects, mats = read_obj(obj_path)
    names = sorted({m for o in objects.values() for m in o}, key=list(mats).index)
    gl = {'asset': {'version': '2.0', 'generator': 'hemirad scenes/tools/obj_to_gltf.py'},
          'extensionsUsed': ['KHR_materials_emissive_strength'], 'scene': 0, 'scenes': [{'nodes': []}],
          'nodes': [], 'meshes': [], 'materials': [], 'accessors': [], 'bufferViews': []}
    for name in names:
        kd, ke = mats[name]['Kd'], mats[name]['Ke']
        m = {'name': name, 'pbrMetallicRoughness': {'baseColorFactor': kd + [1.0], 'metallicFactor': 0.0}}
        strength = max(ke)
        if strength > 0:
            m['emissiveFactor'] = [x / strength for x in ke]
            if strength != 1: m['extensions'] = {'KHR_materials_emissive_strength': {'emissiveStrength': strength}}
        gl['materials'].append(m)
    blob = bytearray()
    def view(data, target):
        while len(blob) % 4: blob.append(0)
        gl['bufferViews'].append({'buffer': 0, 'byteOffset': len(blob), 'byteLength': len(data), 'target': target})
        blob.extend(data)
        return len(gl['bufferViews']) - 1
    for obj, by_mat in objects.items():
        prims = []
        for mat, faces in by_mat.items():
            pos, idx = [], []
            for f in faces:
                base = len(pos)
                pos += f
                for k in range(1, len(f) - 1): idx += [base, base + k, base + k + 1]
            lo = [min(p[i] for p in pos) for i in range(3)]
            hi = [max(p[i] for p in pos) for i in range(3)]
            pv = view(struct.pack(f'<{3 * len(pos)}f', *[x for p in pos for x in p]), 34962)
            iv = view(struct.pack(f'<{len(idx)}I', *idx), 34963)
            gl['accessors'] += [{'bufferView': pv, 'componentType': 5126, 'count': len(pos), 'type': 'VEC3',
                                 'min': lo, 'max': hi},
                                {'bufferView': iv, 'componentType': 5125, 'count': len(idx), 'type': 'SCALAR'}]
            n = len(gl['accessors'])
            prims.append({'attributes': {'POSITION': n - 2}, 'indices': n - 1, 'material': names.index(mat)})
        gl['meshes'].append({'name': obj, 'primitives': prims})
        gl['nodes'].append({'name': obj, 'mesh': len(gl['meshes']) - 1})
    cam_path = os.path.splitext(obj_path)[0] + '.camera'
    if os.path.exists(cam_path):
        node, yfov = camera_node(cam_path)
        gl['cameras'] = [{'type': 'perspective', 'perspective': {'yfov': yfov, 'znear': 1e-3, 'aspectRatio': 1.0}}]
        gl['nodes'].append(node)
    gl['scenes'][0]['nodes'] = list(range(len(gl['nodes'])))
    gl['buffers'] = [{'byteLength': len(blob),
                      'uri': 'data:application/octet-stream;base64,' + base64.b64encode(bytes(blob)).decode()}]
    with open(out_path, 'w') as f:
        json.dump(gl, f, indent=1)
        f.write('\n')

if __name__ == '__main__':
    main(*sys.argv[1:3])
