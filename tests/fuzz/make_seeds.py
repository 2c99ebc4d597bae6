#!/usr/bin/python3
"""Writes the seed corpora of the fuzz targets (tests/fuzz/corpus/TARGET/), small files of our
own making: one valid input of each kind the target reads, so that fuzzing starts from the
grammar rather than from nothing. Deterministic; run it again after changing it and commit the
output (the corpora stay well under 50 KB).

    /usr/bin/python3 tests/fuzz/make_seeds.py
"""
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "corpus")

# A tetrahedron: the smallest closed mesh (corner 0 at the origin, three unit axes).
TETRA_V = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
# The mesh loader target picks the format by the first byte (mesh_loader_fuzzer.cpp).
FORMAT_BYTE = {"obj": 0, "stl": 1, "ply": 2, "off": 3, "dae": 4}


def write(target, name, data):
    os.makedirs(os.path.join(CORPUS, target), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(CORPUS, target, name), "wb") as f:
        f.write(data)


def mesh_seed(name, fmt, data):
    if isinstance(data, str):
        data = data.encode()
    write("mesh_loader", name, bytes([FORMAT_BYTE[fmt]]) + data)


def obj_seeds():
    cube = ("# cube with quads, a normal, a texture coordinate, a group and a line\n"
            "o cube\ng side\n"
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "vn 0 0 1\nvt 0.5 0.5\n"
            "f 1/1/1 4/1/1 3/1/1 2/1/1\nf 5//1 6//1 7//1 8//1\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf -4 -8 -7 -3\n"
            "l 1 7\np 2\n")
    mesh_seed("cube.obj", "obj", cube)
    tetra = "".join("v %g %g %g\n" % v for v in TETRA_V) + "".join(
        "f %d %d %d\n" % tuple(i + 1 for i in f) for f in TETRA_F)
    mesh_seed("tetra.obj", "obj", tetra)


def stl_seeds():
    def normal_free_facets():
        out = []
        for f in TETRA_F:
            out.append([TETRA_V[i] for i in f])
        return out

    text = "solid tetra\n"
    for tri in normal_free_facets():
        text += " facet normal 0 0 0\n  outer loop\n"
        for v in tri:
            text += "   vertex %g %g %g\n" % v
        text += "  endloop\n endfacet\n"
    text += "endsolid tetra\n"
    mesh_seed("tetra_ascii.stl", "stl", text)
    binary = b"binary tetra".ljust(80, b" ") + struct.pack("<I", len(TETRA_F))
    for tri in normal_free_facets():
        binary += struct.pack("<3f", 0, 0, 0)
        for v in tri:
            binary += struct.pack("<3f", *v)
        binary += b"\0\0"
    mesh_seed("tetra_binary.stl", "stl", binary)


def ply_seeds():
    def header(fmt):
        return ("ply\nformat %s 1.0\ncomment tetrahedron\nelement vertex 4\n"
                "property float x\nproperty float y\nproperty float z\n"
                "element face 4\nproperty list uchar int vertex_indices\nend_header\n" % fmt)

    text = header("ascii") + "".join("%g %g %g\n" % v for v in TETRA_V) + "".join(
        "3 %d %d %d\n" % f for f in TETRA_F)
    mesh_seed("tetra_ascii.ply", "ply", text)
    for fmt, order in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
        body = b"".join(struct.pack(order + "3f", *v) for v in TETRA_V)
        body += b"".join(struct.pack(order + "B3i", 3, *f) for f in TETRA_F)
        mesh_seed("tetra_%s.ply" % fmt, "ply", header(fmt).encode() + body)


def off_seeds():
    text = "OFF\n# tetrahedron\n4 4 6\n" + "".join("%g %g %g\n" % v for v in TETRA_V) + "".join(
        "3 %d %d %d\n" % f for f in TETRA_F)
    mesh_seed("tetra.off", "off", text)
    quad = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"
    mesh_seed("quad.off", "off", quad)


def dae_seeds():
    positions = " ".join("%g %g %g" % v for v in TETRA_V)
    indices = " ".join("%d %d %d" % f for f in TETRA_F)
    doc = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<asset><unit name="centimeter" meter="0.01"/><up_axis>Z_UP</up_axis></asset>
<library_geometries><geometry id="t" name="t"><mesh>
<source id="p"><float_array id="pa" count="12">%s</float_array>
<technique_common><accessor source="#pa" count="4" stride="3">
<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
</accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="4"><input semantic="VERTEX" source="#v" offset="0"/><p>%s</p></triangles>
<polylist count="1"><input semantic="VERTEX" source="#v" offset="0"/><vcount>4</vcount><p>0 1 2 3</p></polylist>
</mesh></geometry></library_geometries>
<library_nodes><node id="lib" name="lib"><instance_geometry url="#t"/></node></library_nodes>
<library_visual_scenes><visual_scene id="s" name="s">
<node id="a" name="a"><translate>1 2 3</translate><rotate>0 0 1 90</rotate><scale>2 2 2</scale>
<instance_geometry url="#t"/>
<node id="b" name="b"><matrix>1 0 0 5 0 1 0 0 0 0 1 0 0 0 0 1</matrix><instance_node url="#lib"/></node>
</node></visual_scene></library_visual_scenes>
<scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
""" % (positions, indices)
    mesh_seed("tetra.dae", "dae", doc)


def cfg_seeds():
    # Named meshes are the two the target writes next to the file (problem_file_fuzzer.cpp).
    se2 = """# SE(2): the robot box between the two world boxes
[problem]
name = fuzz_se2
robot = robot.obj
world = world.obj
start.x = 0
start.y = 0
start.theta = 0
goal.x = 0
goal.y = 0.5
goal.theta = 1.5707963267948966
volume.min.x = -2
volume.min.y = -2
volume.max.x = 2
volume.max.y = 2
objective = max_min_clearance
objective.threshold = 0.5
longest_valid_segment_fraction = 0.01
sampler = obstacle_based

[benchmark]
time_limit = 10
mem_limit = 4000
run_count = 3
simplify = 1
save_paths = shortest
output = out

[planner]
rrtconnect =
rrtconnect.range = 0.3
prm =
prm.name = PRM-a
prm.max_nearest_neighbors = 5
"""
    write("problem_file", "se2.cfg", se2)
    se3 = """[problem]
robot = robot.obj
world = world.obj
start.x = 0
start.y = 0
start.z = 0
start.theta = 0.3
start.axis.x = 0
start.axis.y = 1
start.axis.z = 1
goal.x = 0
goal.y = 0
goal.z = 0.5
goal.theta = 0
goal.axis.x = 1
goal.axis.y = 0
goal.axis.z = 0
objective = length
[planner]
rrtstar =
"""
    write("problem_file", "se3.cfg", se3)
    # No volume: bounds inferred from the world; a start in collision; an unknown section.
    write("problem_file", "inferred.cfg",
          "[problem]\nrobot=robot.obj\nworld=world.obj\nstart.x=0.7\nstart.y=0\nstart.theta=0\n"
          "goal.x=0\ngoal.y=0\ngoal.theta=0\n[display]\ncolour = red\n")


def pose_seeds():
    write("pose_file", "poses.txt",
          "# tx ty tz qw qx qy qz (A), then B\n"
          "0 0 0 1 0 0 0   3 0 0 1 0 0 0\n"
          "\n"
          "0 0 0 1 0 0 0   0 0 6 0.70710678118654752 0 0 0.70710678118654752  # turned\r\n"
          "-2e0 0 0 1 0 0 0   2 0 0 1.0000001 0 0 0\n")
    write("pose_file", "one.txt", "1.5 -2.25 1e-3 0.5 0.5 0.5 0.5 0 0 0 0 0 1 0")


def distance_seed(name, flags, parameter, mesh_a, mesh_b, pose_a, pose_b, pack):
    """flags/parameter as decodeScene in distance_fuzzer.cpp reads them; meshes as (vertices,
    triangles); poses as (tx, ty, tz, qw, qx, qy, qz); pack encodes one number."""
    (va, fa), (vb, fb) = mesh_a, mesh_b
    out = bytes([flags, parameter & 0xff, len(va) - 3, len(fa) - 1, len(vb) - 3, len(fb) - 1])
    for p in (pose_a, pose_b):
        out += b"".join(pack(x) for x in p)
    for v in va + vb:
        out += b"".join(pack(x) for x in v)
    for f in fa + fb:
        out += bytes(f)
    write("distance", name, out)


def distance_seeds():
    f64 = lambda x: struct.pack("<d", x)
    i8 = lambda x: struct.pack("<b", int(x))
    i16 = lambda x: struct.pack("<h", int(round(x * 256)))
    cube_v = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
    cube_f = [(0, 2, 1), (1, 2, 3), (4, 5, 6), (5, 7, 6), (0, 1, 4), (1, 5, 4),
              (2, 6, 3), (3, 6, 7), (0, 4, 2), (2, 4, 6), (1, 3, 5), (3, 7, 5)]
    tetra = (TETRA_V, TETRA_F)
    cube = (cube_v, cube_f)
    ident = (0, 0, 0, 1, 0, 0, 0)
    # Two cubes one unit apart, face to face (exactly parallel faces), raw doubles.
    distance_seed("cubes_f64", 0x00, 0, cube, cube, ident, (3, 0, 0, 1, 0, 0, 0), f64)
    # Interpenetrating cubes turned 45 degrees about z, small-integer grid (qw = qz = 1, normalized).
    distance_seed("cubes_turned_i8", 0x01, 0, cube, cube, ident, (1, 0, 0, 1, 0, 0, 1), i8)
    # Tetrahedron near a cube corner on the fine grid, with hierarchies, threshold check.
    distance_seed("tetra_cube_i16", 0x16, 4, tetra, cube, (1.00390625, 1, 1, 1, 0, 0, 0), ident, i16)
    # The same at a scale of 2^-12 and 2^12, cap and tolerance checks.
    distance_seed("tetra_cube_small", 0x23, -12, tetra, cube, (2, 1, 1, 1, 0, 0, 0), ident, i8)
    distance_seed("tetra_cube_large", 0x33, 12, tetra, cube, (2, 1, 1, 1, 0, 0, 0), ident, i8)
    # Coplanar triangles, one inside the other's plane, offset by 1e6.
    tri_a = ([(0, 0, 0), (4, 0, 0), (0, 4, 0)], [(0, 1, 2)])
    tri_b = ([(1, 1, 0), (3, 1, 0), (1, 3, 0)], [(0, 1, 2)])
    distance_seed("coplanar_offset_f64", 0x10, 2, tri_a, tri_b, (1e6, 1e6, 0, 1, 0, 0, 0),
                  (1e6, 1e6, 0, 1, 0, 0, 0), f64)


# The MotionBenchMaker target picks the reader by the first byte (motion_bench_maker_fuzzer.cpp).
MBM_SCENE = """name: seed
robot_state:
  joint_state: {name: [j1, j2], position: [0.5, -1.25]}
world:
  collision_objects:
    - id: table
      header: {frame_id: world}
      pose:
        position: {x: 1, y: 0, z: 0}
        orientation: {x: 0, y: 0, z: 0.7071067811865476, w: 0.7071067811865476}
      primitives:
        - type: box
          dimensions: [0.4, 0.2, 0.1]
        - {type: cylinder, dimensions: [0.6, 0.05]}
      primitive_poses:
        - position: {x: 0.5, y: 0, z: 0.2}
          orientation: {x: 0, y: 0, z: 0, w: 1}
        - position: [0, 0, 1]
          orientation: [0.7071067811865476, 0, 0, 0.7071067811865476]
    - id: ball
      primitives: [{type: 2, dimensions: [0.1]}]
      primitive_poses: [{position: [0, -1, 0.5]}]
    - id: sheet
      meshes:
        - vertices: [[0, 0, 0], [1, 0, 0], {x: 0, y: 1, z: 0}]
          triangles: [{vertex_indices: [0, 1, 2]}, [2, 1, 0]]
      mesh_poses: [{position: [0, 0, 2], orientation: [0, 0, 1, 0]}]
"""
MBM_REQUEST = """group_name: manipulator
allowed_planning_time: 5.5
start_state:
  joint_state:
    name: [a, b]
    position: [0.1, -0.2]
goal_constraints:
  - joint_constraints:
      - {joint_name: a, position: 1.5, tolerance_above: 0.001, tolerance_below: 0.002}
      - joint_name: b
        position: -1e-1
        tolerance_above: 0
        tolerance_below: 0
"""
MBM_CFG = """# an arm problem
[problem]
name = seed
robot = ${ADSD_ROBOTS}/KR5/KR5 sixx R650.urdf
srdf = kr5.srdf
scene = scene.yaml
request = request.yaml
package_path = ${ADSD_ROBOTS}:extra
"""


def motion_bench_maker_seeds():
    write("motion_bench_maker", "scene.yaml", bytes([0]) + MBM_SCENE.encode())
    write("motion_bench_maker", "request.yaml", bytes([1]) + MBM_REQUEST.encode())
    write("motion_bench_maker", "problem.cfg", bytes([3]) + MBM_CFG.encode())


def main():
    shutil.rmtree(CORPUS, ignore_errors=True)
    obj_seeds()
    stl_seeds()
    ply_seeds()
    off_seeds()
    dae_seeds()
    cfg_seeds()
    pose_seeds()
    distance_seeds()
    motion_bench_maker_seeds()
    total = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(CORPUS) for f in fs)
    print("seed corpora written to %s: %d bytes" % (CORPUS, total))


if __name__ == "__main__":
    main()
