"""Build PhongLab's Blender-made meshes and export them as OBJ.

Run from the repository root (Blender 3.4 or later, headless):

    blender -b --factory-startup -P assets/blender/make_assets.py
    blender -b --factory-startup -P assets/blender/make_assets.py -- --out /tmp/x

`--out DIR` writes the same relative paths under DIR instead of the
repository root (handy for comparing a regeneration with the committed files).

What it writes (paths relative to the repository root or --out):

    assets/meshes/tree.obj               low-poly tree, smooth shaded, with normals
    assets/meshes/tree_flat.obj          the same tree, flat shaded (one vn per face)
    assets/meshes/tree_nonormals.obj     the same tree, no vn lines
    assets/meshes/cloud.obj              cloud (puffs unioned by voxel remesh), smooth
    assets/meshes/cloud_flat.obj         the same cloud, flat shaded
    assets/meshes/cloud_nonormals.obj    the same cloud, no vn lines
    tests/data/meshes/blender/cube_flat.obj        2x2x2 cube at the origin, 6 quads, 6 vn
    tests/data/meshes/blender/cube_smooth.obj      the same cube, smooth (8 vn, corner diagonals)
    tests/data/meshes/blender/sphere_smooth.obj    UV sphere r=1, 32 segments x 16 rings, smooth
    tests/data/meshes/blender/sphere_nonormals.obj the same sphere, no vn lines

Every file is exported with Blender's C++ OBJ exporter (bpy.ops.wm.obj_export)
with Y up and -Z forward: a point (x, y, z) in Blender (Z up) is written as
(x, z, -y). No materials (.mtl), no UVs, polygons are kept as they are (quads and
n-gons are not triangulated). The tree stands on y = 0 with its trunk on the
y axis and is 2 units tall; the cloud is 2 units wide in x, centred on the origin.

The build is deterministic: all jitter comes from random.Random with fixed
seeds, and the script re-runs itself as `blender -t 1 ...` when it was not
started single-threaded, because Blender's multi-threaded normal sums, voxel
remesh and decimation change the last digits of a few numbers from run to
run. With one thread the files are byte-for-byte identical between runs (of
the same Blender version). After exporting, every file is re-read in plain Python and
checked (index ranges, bounds, normal lengths, file size < 1 MB for the assets,
cube_flat's six axis normals with one vn per face); a table is printed and the
script exits with status 1 if a check fails.
"""

import math
import os
import random
import sys

import bmesh
import bpy
from mathutils import Vector

TREE_SEED = 20240611
CLOUD_SEED = 7041


# --------------------------------------------------------------------------
# scene helpers

def clear_scene():
    """Remove everything --factory-startup puts in the scene (cube, camera, light)."""
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)
    for coll in (bpy.data.meshes, bpy.data.cameras, bpy.data.lights,
                 bpy.data.materials, bpy.data.metaballs):
        for block in list(coll):
            coll.remove(block)


def object_from_bmesh(name, bm):
    mesh = bpy.data.meshes.new(name)
    bm.normal_update()
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def set_smooth(obj, smooth):
    mesh = obj.data
    if hasattr(mesh, "use_auto_smooth"):
        mesh.use_auto_smooth = False  # one normal per vertex when smooth
    mesh.polygons.foreach_set("use_smooth", [smooth] * len(mesh.polygons))
    mesh.update()


def select_only(obj):
    for other in bpy.context.view_layer.objects:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def export_obj(obj, path, normals):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    select_only(obj)
    bpy.ops.wm.obj_export(
        filepath=path,
        export_selected_objects=True,
        apply_modifiers=True,
        export_normals=normals,
        export_uv=False,
        export_materials=False,
        export_triangulated_mesh=False,
        forward_axis='NEGATIVE_Z',
        up_axis='Y',
    )
    print(f"wrote {path}")


def export_variants(obj, base_path, flat_too=True):
    """base.obj (smooth), base_flat.obj, base_nonormals.obj."""
    set_smooth(obj, True)
    export_obj(obj, base_path + ".obj", normals=True)
    if flat_too:
        set_smooth(obj, False)
        export_obj(obj, base_path + "_flat.obj", normals=True)
    set_smooth(obj, True)
    export_obj(obj, base_path + "_nonormals.obj", normals=False)


def apply_modifiers(obj):
    """Replace obj's mesh by its evaluated mesh (all modifiers applied), context-free."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = obj.evaluated_get(depsgraph)
    new_mesh = bpy.data.meshes.new_from_object(evaluated)
    old_mesh = obj.data
    obj.modifiers.clear()
    obj.data = new_mesh
    bpy.data.meshes.remove(old_mesh)


def normalize(obj, center_xy, base_z=None, height=None, width_x=None):
    """Scale uniformly and translate the mesh data (Blender coordinates, Z up)."""
    mesh = obj.data
    xs = [v.co.x for v in mesh.vertices]
    ys = [v.co.y for v in mesh.vertices]
    zs = [v.co.z for v in mesh.vertices]
    scale = 1.0
    if height is not None:
        scale = height / (max(zs) - min(zs))
    elif width_x is not None:
        scale = width_x / (max(xs) - min(xs))
    if center_xy == "bbox":
        cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    else:
        cx, cy = 0.0, 0.0
    cz = min(zs) if base_z is not None else (min(zs) + max(zs)) / 2
    target_z = base_z if base_z is not None else 0.0
    for v in mesh.vertices:
        v.co = Vector(((v.co.x - cx) * scale, (v.co.y - cy) * scale,
                       (v.co.z - cz) * scale + target_z))
    mesh.update()


# --------------------------------------------------------------------------
# tree

def frame_for(tangent):
    t = tangent.normalized()
    ref = Vector((0, 0, 1)) if abs(t.z) < 0.9 else Vector((1, 0, 0))
    u = t.cross(ref).normalized()
    v = t.cross(u).normalized()
    return u, v


def add_tube(bm, points, radii, segments, rng, jitter=0.0, tip=True):
    """A closed, tapered tube along `points`: the start is closed by an n-gon,
    the end by a single tip vertex (tip=True) or an n-gon."""
    rings = []
    n = len(points)
    for i, (p, r) in enumerate(zip(points, radii)):
        if i == 0:
            tangent = points[1] - points[0]
        elif i == n - 1:
            tangent = points[-1] - points[-2]
        else:
            tangent = points[i + 1] - points[i - 1]
        u, v = frame_for(tangent)
        ring = []
        for s in range(segments):
            a = 2 * math.pi * s / segments
            rr = r * (1.0 + rng.uniform(-jitter, jitter)) if 0 < i < n - 1 else r
            ring.append(bm.verts.new(p + rr * (math.cos(a) * u + math.sin(a) * v)))
        rings.append(ring)
    for i in range(n - 1):
        a, b = rings[i], rings[i + 1]
        for s in range(segments):
            t = (s + 1) % segments
            bm.faces.new((a[s], a[t], b[t], b[s]))
    bm.faces.new(list(reversed(rings[0])))
    last = rings[-1]
    if tip:
        d = (points[-1] - points[-2]).normalized()
        apex = bm.verts.new(points[-1] + d * radii[-1] * 1.5)
        for s in range(segments):
            t = (s + 1) % segments
            bm.faces.new((last[s], last[t], apex))
    else:
        bm.faces.new(last)


def add_cone_layer(bm, base_z, radius, height, segments, rings, rng):
    """A jittered cone: serrated, drooping rim, apex on the axis, and a
    concave underside fanned to a centre vertex."""
    twist = rng.uniform(0, 2 * math.pi)
    grid = []
    for k in range(rings):  # ring k = 0 is the rim
        t = k / rings
        ring = []
        wobble = rng.uniform(-0.08, 0.08)
        for s in range(segments):
            a = twist + 2 * math.pi * (s + wobble) / segments
            r = radius * (1 - t) ** 1.1 * (1 + rng.uniform(-0.045, 0.045))
            z = base_z + height * t + rng.uniform(-0.01, 0.01)
            if k == 0:  # serrated rim: every other point reaches out and droops
                if s % 2 == 0:
                    r *= 1.08
                    z -= 0.07
                else:
                    r *= 0.95
            ring.append(bm.verts.new((r * math.cos(a), r * math.sin(a), z)))
        grid.append(ring)
    for k in range(rings - 1):
        a, b = grid[k], grid[k + 1]
        for s in range(segments):
            t = (s + 1) % segments
            bm.faces.new((a[s], a[t], b[t], b[s]))
    apex = bm.verts.new((rng.uniform(-0.01, 0.01), rng.uniform(-0.01, 0.01), base_z + height))
    top = grid[-1]
    for s in range(segments):
        t = (s + 1) % segments
        bm.faces.new((top[s], top[t], apex))
    under = bm.verts.new((0, 0, base_z + 0.18 * height))
    rim = grid[0]
    for s in range(segments):
        t = (s + 1) % segments
        bm.faces.new((rim[t], rim[s], under))


def build_tree():
    rng = random.Random(TREE_SEED)
    bm = bmesh.new()

    # trunk: tapered, flared at the base, slightly leaning, planar n-gon at z = 0
    trunk_pts, trunk_r = [], []
    levels = 9
    for i in range(levels):
        t = i / (levels - 1)
        z = 1.15 * t
        lean = 0.03 * math.sin(2.2 * t)
        trunk_pts.append(Vector((lean, 0.5 * lean, z)))
        trunk_r.append(0.075 + 0.05 * (1 - t) + 0.06 * max(0.0, 1 - 4 * t) ** 2)
    add_tube(bm, trunk_pts, trunk_r, segments=16, rng=rng, jitter=0.04, tip=False)

    # three roots running from inside the trunk down to the ground
    for i in range(3):
        ang = 2 * math.pi * i / 3 + rng.uniform(-0.3, 0.3)
        d = Vector((math.cos(ang), math.sin(ang), 0))
        reach = rng.uniform(0.30, 0.38)
        pts = [d * 0.04 + Vector((0, 0, 0.20)),
               d * (0.45 * reach) + Vector((0, 0, 0.10)),
               d * (0.80 * reach) + Vector((0, 0, 0.04)),
               d * reach + Vector((0, 0, 0.025))]
        add_tube(bm, pts, [0.08, 0.06, 0.04, 0.025], segments=8, rng=rng,
                 jitter=0.05, tip=True)

    # two short branches poking out under the lowest canopy layer
    for i in range(2):
        ang = math.pi * i + rng.uniform(0.2, 0.8)
        d = Vector((math.cos(ang), math.sin(ang), 0))
        z0 = 0.52 + 0.08 * i
        pts = [d * 0.03 + Vector((0, 0, z0)),
               d * 0.22 + Vector((0, 0, z0 + 0.10)),
               d * 0.40 + Vector((0, 0, z0 + 0.24))]
        add_tube(bm, pts, [0.04, 0.028, 0.014], segments=8, rng=rng,
                 jitter=0.05, tip=True)

    # canopy: three stacked, jittered cones
    layers = [  # base z, radius, height
        (0.72, 0.78, 0.80),
        (1.10, 0.62, 0.72),
        (1.44, 0.44, 0.68),
    ]
    for base_z, radius, height in layers:
        add_cone_layer(bm, base_z, radius, height, segments=32, rings=12, rng=rng)

    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    obj = object_from_bmesh("Tree", bm)
    # base on z = 0 (Blender) -> y = 0 (OBJ), trunk stays on the axis, 2 units tall
    normalize(obj, center_xy="axis", base_z=0.0, height=2.0)
    return obj


# --------------------------------------------------------------------------
# cloud

def build_cloud():
    rng = random.Random(CLOUD_SEED)
    bm = bmesh.new()
    puffs = [((0.0, 0.0, 0.05), 0.62)]
    # a ring of lower puffs around the centre, and a few on top
    for i in range(6):
        a = 2 * math.pi * i / 6 + rng.uniform(-0.25, 0.25)
        d = rng.uniform(0.55, 0.80)
        puffs.append(((d * math.cos(a) * 1.25, d * math.sin(a) * 0.75, rng.uniform(-0.12, 0.0)),
                      rng.uniform(0.36, 0.48)))
    for i in range(3):
        a = 2 * math.pi * i / 3 + rng.uniform(-0.4, 0.4)
        puffs.append(((0.35 * math.cos(a), 0.25 * math.sin(a), rng.uniform(0.30, 0.45)),
                      rng.uniform(0.32, 0.42)))
    for center, radius in puffs:
        geom = bmesh.ops.create_icosphere(bm, subdivisions=3, radius=radius)
        verts = geom["verts"]
        for v in verts:
            v.co += Vector(center)
            v.co.z = max(v.co.z, -0.22)  # flatten the bottom of each puff a little
    obj = object_from_bmesh("Cloud", bm)

    # union the overlapping puffs into one closed surface, then go low-poly
    remesh = obj.modifiers.new("Remesh", 'REMESH')
    remesh.mode = 'VOXEL'
    remesh.voxel_size = 0.035
    remesh.adaptivity = 0.0
    apply_modifiers(obj)
    tris = sum(len(p.vertices) - 2 for p in obj.data.polygons)
    target = 3000
    decimate = obj.modifiers.new("Decimate", 'DECIMATE')
    decimate.decimate_type = 'COLLAPSE'
    decimate.ratio = min(1.0, target / tris)
    decimate.use_collapse_triangulate = True
    apply_modifiers(obj)
    normalize(obj, center_xy="bbox", width_x=2.0)
    return obj


# --------------------------------------------------------------------------
# test meshes

def build_cube():
    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=2.0)
    return object_from_bmesh("Cube", bm)


def build_uv_sphere(segments=32, rings=16):
    """Blender's UV sphere (same vertices and faces as Add > UV Sphere, radius 1),
    built here because bmesh.ops.create_uvsphere welds its vertices through a
    hash and the face order then changes from run to run. Poles on Blender's Z
    axis (the file's Y axis); ring k at polar angle pi*k/rings; triangles at
    the poles, quads between."""
    bm = bmesh.new()
    north = bm.verts.new((0.0, 0.0, 1.0))
    grid = []
    for k in range(1, rings):
        theta = math.pi * k / rings
        ring = []
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            ring.append(bm.verts.new((math.sin(theta) * math.cos(phi),
                                      math.sin(theta) * math.sin(phi),
                                      math.cos(theta))))
        grid.append(ring)
    south = bm.verts.new((0.0, 0.0, -1.0))
    for s in range(segments):
        t = (s + 1) % segments
        bm.faces.new((north, grid[0][s], grid[0][t]))
    for k in range(rings - 2):
        a, b = grid[k], grid[k + 1]
        for s in range(segments):
            t = (s + 1) % segments
            bm.faces.new((a[s], b[s], b[t], a[t]))
    for s in range(segments):
        t = (s + 1) % segments
        bm.faces.new((grid[-1][t], grid[-1][s], south))
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    return object_from_bmesh("Sphere", bm)


# --------------------------------------------------------------------------
# checks

class ObjStats:
    def __init__(self, path):
        self.path = path
        self.size = os.path.getsize(path)
        self.v, self.vn, self.faces = [], [], []
        self.other = {}
        with open(path, encoding="ascii") as f:
            for line in f:
                parts = line.split()
                if not parts or parts[0].startswith("#"):
                    continue
                tag = parts[0]
                if tag == "v":
                    self.v.append(tuple(float(x) for x in parts[1:4]))
                elif tag == "vn":
                    self.vn.append(tuple(float(x) for x in parts[1:4]))
                elif tag == "f":
                    corners = []
                    for c in parts[1:]:
                        idx = c.split("/")
                        vi = int(idx[0])
                        ni = int(idx[2]) if len(idx) == 3 and idx[2] else None
                        corners.append((vi, ni))
                    self.faces.append(corners)
                else:
                    self.other[tag] = self.other.get(tag, 0) + 1
        self.triangles = sum(len(f) - 2 for f in self.faces)
        self.bounds = [(min(p[i] for p in self.v), max(p[i] for p in self.v)) for i in range(3)]


def check(stats, errors, max_size=None, want_normals=True):
    name = os.path.relpath(stats.path)
    def fail(msg):
        errors.append(f"{name}: {msg}")
    if any(t in stats.other for t in ("vt", "mtllib", "usemtl")):
        fail(f"unexpected lines {stats.other}")
    if want_normals != bool(stats.vn):
        fail(f"vn lines: {len(stats.vn)}, wanted {'some' if want_normals else 'none'}")
    for f in stats.faces:
        if len(f) < 3:
            fail("face with fewer than 3 corners")
        for vi, ni in f:
            if not 1 <= vi <= len(stats.v):
                fail(f"position index {vi} out of range")
            if want_normals and (ni is None or not 1 <= ni <= len(stats.vn)):
                fail(f"normal index {ni} out of range")
            if not want_normals and ni is not None:
                fail("normal index in a file without normals")
    for n in stats.vn:
        length = math.sqrt(sum(c * c for c in n))
        if abs(length - 1) > 2e-3:
            fail(f"normal {n} has length {length}")
            break
    if max_size is not None and stats.size >= max_size:
        fail(f"{stats.size} bytes >= {max_size}")
    check_closed_outward(stats, errors)


def check_closed_outward(stats, errors):
    """Every edge is shared by exactly two faces (closed, manifold shells) and
    every shell encloses a positive volume (corners counter-clockwise seen
    from outside, as OpenGL's default front face wants)."""
    name = os.path.relpath(stats.path)
    parent = list(range(len(stats.v)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    edges = {}
    for f in stats.faces:
        idx = [vi - 1 for vi, _ in f]
        for i, a in enumerate(idx):
            b = idx[(i + 1) % len(idx)]
            key = (min(a, b), max(a, b))
            edges[key] = edges.get(key, 0) + 1
            parent[find(a)] = find(b)
    if any(count != 2 for count in edges.values()):
        errors.append(f"{name}: not closed (an edge is not shared by exactly two faces)")
    volume = {}
    for f in stats.faces:
        p = [stats.v[vi - 1] for vi, _ in f]
        shell = find(f[0][0] - 1)
        for i in range(1, len(p) - 1):
            a, b, c = p[0], p[i], p[i + 1]
            det = (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                   + a[2] * (b[0] * c[1] - b[1] * c[0]))
            volume[shell] = volume.get(shell, 0.0) + det / 6
    if min(volume.values()) <= 0:
        errors.append(f"{name}: a shell is inside out (volume {min(volume.values())})")
    stats.shells = len(volume)


def check_flat_normals(stats, errors):
    """Every face uses one vn for all its corners."""
    for f in stats.faces:
        if len({ni for _, ni in f}) != 1:
            errors.append(f"{os.path.relpath(stats.path)}: face corners use different vn")
            return


def check_cube_flat(stats, errors):
    check_flat_normals(stats, errors)
    axes = {(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)}
    got = {tuple(int(round(c)) for c in n) for n in stats.vn}
    exact = all(abs(c - round(c)) < 1e-6 for n in stats.vn for c in n)
    if len(stats.vn) != 6 or got != axes or not exact:
        errors.append(f"cube_flat: normals {stats.vn}")
    if len(stats.v) != 8 or len(stats.faces) != 6 or any(len(f) != 4 for f in stats.faces):
        errors.append("cube_flat: expected 8 v and 6 quads")
    # each face's normal points away from the centre: all its corners have
    # the normal's non-zero coordinate equal to the normal's sign
    for f in stats.faces:
        n = stats.vn[f[0][1] - 1]
        axis = max(range(3), key=lambda i: abs(n[i]))
        if any(abs(stats.v[vi - 1][axis] - n[axis]) > 1e-6 for vi, _ in f):
            errors.append("cube_flat: a face normal does not point outward")
            break
    for lo, hi in stats.bounds:
        if abs(lo + 1) > 1e-6 or abs(hi - 1) > 1e-6:
            errors.append(f"cube_flat: bounds {stats.bounds}")
            break


def check_sphere(stats, errors, smooth):
    if len(stats.v) != 32 * 15 + 2 or len(stats.faces) != 32 * 16:
        errors.append(f"{stats.path}: {len(stats.v)} v, {len(stats.faces)} f")
    for p in stats.v:
        if abs(math.sqrt(sum(c * c for c in p)) - 1) > 1e-5:
            errors.append(f"{stats.path}: vertex {p} not on the unit sphere")
            break
    if smooth:
        # each corner's normal is close to its vertex's position: Blender averages
        # the face normals (weighted by corner angle), which on a UV sphere leans
        # up to ~0.2 degrees away from the radius, and writes 4 decimals
        cos_limit = math.cos(math.radians(0.5))
        for f in stats.faces:
            for vi, ni in f:
                p, n = stats.v[vi - 1], stats.vn[ni - 1]
                cos = sum(a * b for a, b in zip(p, n)) / math.sqrt(sum(c * c for c in n))
                if cos < cos_limit:
                    errors.append(f"{stats.path}: normal {n} at vertex {p}")
                    return


def print_table(all_stats, root):
    header = (f"{'file':44} {'v':>6} {'vn':>6} {'f':>6} {'tris':>6} {'shells':>6} "
              f"{'bytes':>8}  bounds (x; y; z)")
    print(header)
    print("-" * len(header) + "-" * 40)
    for s in all_stats:
        b = "; ".join(f"{lo:+.3f}..{hi:+.3f}" for lo, hi in s.bounds)
        print(f"{os.path.relpath(s.path, root):44} {len(s.v):6} {len(s.vn):6} "
              f"{len(s.faces):6} {s.triangles:6} {s.shells:6} {s.size:8}  {b}")


# --------------------------------------------------------------------------

def single_threaded():
    """True when Blender was started with `-t 1` / `--threads 1`."""
    own = sys.argv[:sys.argv.index("--")] if "--" in sys.argv else sys.argv
    return any(a in ("-t", "--threads") and b == "1" for a, b in zip(own, own[1:]))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if not single_threaded():
        # Blender sums face normals into vertex normals, and the voxel remesh and
        # decimation run, on several threads, so the last decimal of a few
        # numbers changes from run to run. One thread makes the files
        # byte-for-byte reproducible: start again with -t 1.
        import subprocess
        cmd = [bpy.app.binary_path, "-b", "--factory-startup", "-t", "1",
               "-P", os.path.abspath(__file__), "--"] + argv
        print("re-running single-threaded:", " ".join(cmd), flush=True)
        sys.exit(subprocess.run(cmd).returncode)
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    out = root
    if argv[:1] == ["--out"] and len(argv) >= 2:
        out = os.path.abspath(argv[1])
    elif argv:
        print("usage: blender -b --factory-startup -P make_assets.py [-- --out DIR]")
        sys.exit(2)

    meshes = os.path.join(out, "assets", "meshes")
    tests = os.path.join(out, "tests", "data", "meshes", "blender")

    clear_scene()
    tree = build_tree()
    export_variants(tree, os.path.join(meshes, "tree"))
    cloud = build_cloud()
    export_variants(cloud, os.path.join(meshes, "cloud"))

    cube = build_cube()
    set_smooth(cube, False)
    export_obj(cube, os.path.join(tests, "cube_flat.obj"), normals=True)
    set_smooth(cube, True)
    export_obj(cube, os.path.join(tests, "cube_smooth.obj"), normals=True)
    sphere = build_uv_sphere()
    set_smooth(sphere, True)
    export_obj(sphere, os.path.join(tests, "sphere_smooth.obj"), normals=True)
    export_obj(sphere, os.path.join(tests, "sphere_nonormals.obj"), normals=False)

    errors = []
    all_stats = []
    for base in ("tree", "cloud"):
        for suffix, normals in (("", True), ("_flat", True), ("_nonormals", False)):
            s = ObjStats(os.path.join(meshes, base + suffix + ".obj"))
            check(s, errors, max_size=1 << 20, want_normals=normals)
            if suffix == "_flat":
                check_flat_normals(s, errors)
            all_stats.append(s)
    tree_s = all_stats[0]
    if abs(tree_s.bounds[1][0]) > 1e-5 or abs(tree_s.bounds[1][1] - 2.0) > 1e-4:
        errors.append(f"tree: y bounds {tree_s.bounds[1]}, wanted 0..2")
    cloud_s = all_stats[3]
    if abs(cloud_s.bounds[0][1] - cloud_s.bounds[0][0] - 2.0) > 1e-4:
        errors.append(f"cloud: x bounds {cloud_s.bounds[0]}, wanted width 2")
    for lo, hi in cloud_s.bounds:
        if abs(lo + hi) > 1e-4:
            errors.append(f"cloud: not centred, bounds {cloud_s.bounds}")
            break

    for name, normals in (("cube_flat", True), ("cube_smooth", True),
                          ("sphere_smooth", True), ("sphere_nonormals", False)):
        s = ObjStats(os.path.join(tests, name + ".obj"))
        check(s, errors, want_normals=normals)
        if name == "cube_flat":
            check_cube_flat(s, errors)
        elif name == "cube_smooth" and len(s.vn) != 8:
            errors.append(f"cube_smooth: {len(s.vn)} vn, wanted 8")
        elif name.startswith("sphere"):
            check_sphere(s, errors, smooth=normals)
        all_stats.append(s)

    print()
    print_table(all_stats, out)
    print()
    if errors:
        for e in errors:
            print("CHECK FAILED:", e)
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except BaseException:  # Blender exits with 0 after an uncaught exception
        import traceback
        traceback.print_exc()
        sys.exit(1)
