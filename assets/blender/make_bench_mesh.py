"""Write a ~1.3 million triangle Blender OBJ for load-time benchmarks.

Not committed: scripts/make-bench-mesh.sh runs it and writes into build/bench/
(or the folder given to it). Directly:

    blender -b --factory-startup -P assets/blender/make_bench_mesh.py -- OUT_DIR

Writes, in OUT_DIR:

    bench_icosphere.obj            icosphere, subdivisions=9 (1,310,720 triangles,
                                   655,362 vertices), displaced by a procedural
                                   clouds texture, smooth shaded, with normals
                                   (`f a//a b//b c//c`)
    bench_icosphere_nonormals.obj  the same mesh without vn lines (`f a b c`)

Same exporter settings as make_assets.py (bpy.ops.wm.obj_export, Y up,
-Z forward, no materials, no UVs). Prints progress, the counts and the sizes.
"""

import os
import sys
import time

import bmesh
import bpy

SUBDIVISIONS = 9  # Blender counts the bare icosahedron as 1: 20 * 4^(9-1) = 1,310,720 triangles


def log(msg, t0=[time.time()]):
    print(f"[{time.time() - t0[0]:6.1f} s] {msg}", flush=True)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 1:
        print("usage: blender -b --factory-startup -P make_bench_mesh.py -- OUT_DIR")
        sys.exit(2)
    out = os.path.abspath(argv[0])
    os.makedirs(out, exist_ok=True)

    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)

    log(f"building icosphere, {SUBDIVISIONS} subdivisions")
    bm = bmesh.new()
    bmesh.ops.create_icosphere(bm, subdivisions=SUBDIVISIONS, radius=1.0)
    mesh = bpy.data.meshes.new("BenchSphere")
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new("BenchSphere", mesh)
    bpy.context.scene.collection.objects.link(obj)

    log("displacing along the normals (clouds texture)")
    tex = bpy.data.textures.new("BenchClouds", 'CLOUDS')
    tex.noise_scale = 0.35
    tex.noise_depth = 3
    disp = obj.modifiers.new("Displace", 'DISPLACE')
    disp.texture = tex
    disp.texture_coords = 'LOCAL'
    disp.strength = 0.25
    disp.mid_level = 0.5
    depsgraph = bpy.context.evaluated_depsgraph_get()
    new_mesh = bpy.data.meshes.new_from_object(obj.evaluated_get(depsgraph))
    obj.modifiers.clear()
    obj.data = new_mesh
    bpy.data.meshes.remove(mesh)
    obj.data.polygons.foreach_set("use_smooth", [True] * len(obj.data.polygons))
    obj.data.update()
    tris = sum(len(p.vertices) - 2 for p in obj.data.polygons)
    log(f"mesh: {len(obj.data.vertices):,} vertices, {tris:,} triangles")

    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    for name, normals in (("bench_icosphere.obj", True), ("bench_icosphere_nonormals.obj", False)):
        path = os.path.join(out, name)
        log(f"exporting {path}")
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

    log("checking")
    for name in ("bench_icosphere.obj", "bench_icosphere_nonormals.obj"):
        path = os.path.join(out, name)
        counts = {"v": 0, "vn": 0, "f": 0}
        with open(path, "rb") as f:
            for line in f:
                tag = line.split(b" ", 1)[0].decode()
                if tag in counts:
                    counts[tag] += 1
        size = os.path.getsize(path)
        print(f"  {path}: {counts['v']:,} v, {counts['vn']:,} vn, {counts['f']:,} f, "
              f"{size:,} bytes ({size / 2**20:.1f} MiB)", flush=True)
        if counts["f"] != tris or (counts["vn"] == 0) == (name == "bench_icosphere.obj"):
            print("  unexpected counts", flush=True)
            sys.exit(1)
    log("done")


if __name__ == "__main__":
    try:
        main()
    except SystemExit:
        raise
    except BaseException:  # Blender exits with 0 after an uncaught exception
        import traceback
        traceback.print_exc()
        sys.exit(1)
