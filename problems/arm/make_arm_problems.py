#!/usr/bin/python3
"""Writes the shipped arm problems in MotionBenchMaker's format (issue 17):

    problems/arm/NAME/scene.yaml     a MoveIt PlanningScene (world.collision_objects)
    problems/arm/NAME/request.yaml   a MoveIt MotionPlanRequest (start state, joint goal)
    problems/arm/NAME/problem.cfg    our arm problem file naming the robot, scene and request

    problems/arm/make_arm_problems.py [--out DIR]      (default: the directory of this script)

Scenes after MotionBenchMaker's families: table pick (a table with objects on it), shelf (a
bookshelf with boards), box (an open box to reach into), cage (bars around the workspace) and slot
(a wall with a narrow slot to reach through); and ours, pillar (a pillar the shortest swing grazes,
for clearance-optimal planning), sized for the two robots of Debian's dart-doc
(problems/data/fetch_robots.sh): the KUKA KR5 sixx R650 (reach about 0.65 m) and the Barrett WAM
(reach about 1 m). Our own geometry only (boxes, cylinders, spheres, and one triangle mesh each);
the robots' URDFs are named through ${ADSD_ROBOTS}, never copied.

Every scene is written in an "arm frame" (x forward, z up, origin on the first joint's axis at the
foot of the base) scaled by the robot's reach, then placed in the URDF's world frame by the
robot's mount (the KR5's URDF stands it on world y-up: rpy -1.57 about x, 0.5 m along -y; the
WAM's base sits at the world origin, its first axis at x 0.22, y 0.14).

Start and goal joint vectors come from the table GOALS below, within the URDFs' joint limits
(checked here against the LIMITS table copied from the URDFs). They were chosen so that the arm
keeps clear of the scene; that they are collision-free is checked by the arm checker once it
exists (problems/arm/README.md), not here.

Python 3 standard library only. Deterministic: the same files every run (tests/arm_problems
compares them with the committed ones).
"""
import argparse
import math
import os
import sys

# ----------------------------------------------------------------------------------------- robots
ROBOTS = {
    "kr5": {
        "urdf": "${ADSD_ROBOTS}/KR5/KR5 sixx R650.urdf",
        "reach": 0.65,
        "group": "manipulator",
        "joints": ["shoulder_yaw", "shoulder_pitch", "elbow_pitch", "elbow_roll", "wrist_pitch", "wrist_roll"],
        # world_T_arm: the URDF's arm_to_world_fixed joint (xyz 0 -0.5 0, rpy -1.57 0 0).
        "mount": ((0.0, -0.5, 0.0), (-1.57, 0.0, 0.0)),
    },
    "wam": {
        "urdf": "${ADSD_ROBOTS}/wam/wam.urdf",
        # Link pairs in contact by design (problems/arm/wam.srdf), as MoveIt's setup assistant
        # would disable them.
        "srdf": "../wam.srdf",
        "reach": 1.0,
        "group": "arm",
        "joints": ["/j1", "/j2", "/j3", "/j4", "/j5", "/j6", "/j7"],
        # world_T_arm: the first joint's axis (/j1 at xyz 0.22 0.14 0.346 in /wam_base = world).
        "mount": ((0.22, 0.14, 0.0), (0.0, 0.0, 0.0)),
    },
}

# Joint limits (radians) as the URDFs give them, in the order of ROBOTS[...]["joints"].
LIMITS = {
    "kr5": [(-2.9671, 2.9671), (-1.745329252, 2.35619449), (-3.647738137, 0.959931089), (-3.3161, 3.3161),
            (-2.094395102, 2.094395102), (-6.24827872, 6.24827872)],
    "wam": [(-2.6, 2.6), (-2.0, 2.0), (-2.8, 2.8), (-0.9, 3.1), (-4.76, 1.24), (-1.6, 1.6), (-3.0, 3.0)],
}

# (start, goal) per problem: radians, in the joint order above. The start is one folded pose per
# robot (the KR5 leaning back with its forearm raised, the WAM with its elbow folded), the goal
# reaches into the scene. Picked by a throw-away search that kept the links' bounding boxes,
# sampled at 2 cm, at least 3 cm from the obstacles (problems/arm/README.md); not yet verified by
# the arm checker.
KR5_START = [0.0, -0.6, -1.2, 0.0, 0.5, 0.0]
WAM_START = [0.0, -0.4, 0.0, 2.4, 0.0, 0.5, 0.0]
WAM_PILLAR_START = [0.9, 0.7, 0.0, 1.5, 0.0, 0.6, 0.0]
GOALS = {
    # The palm (KR5) or the last link (WAM) above the table's middle, between the objects.
    "kr5_table_pick": (KR5_START, [0.041, 0.43, 0.771, -0.413, 0.928, -1.457]),
    "wam_table_pick": (WAM_START, [0.137, 0.621, -0.115, 2.32, -0.123, 1.308, -0.752]),
    # Into the shelf's second level.
    "kr5_shelf": (KR5_START, [-0.008, 0.218, 0.778, -3.138, 0.886, -1.345]),
    "wam_shelf": (WAM_START, [0.218, 0.87, -0.533, 1.195, -1.485, 1.223, -0.527]),
    # Down into the bin.
    "kr5_box": (KR5_START, [0.03, 0.472, 0.761, 1.509, -0.243, 0.42]),
    "wam_box": (WAM_START, [0.016, 0.823, -0.023, 1.841, 1.067, 0.292, 0.298]),
    # Through the slot: the KR5's forearm straight forward (the upper arm upright); the WAM's arm
    # straight forward at the height of its shoulder, turned about its own axis so that its upper
    # arm's thin side is vertical, the forearm and hand through the slot (the wall stands just
    # beyond the upper arm, SLOT below).
    "kr5_slot": (KR5_START, [0.0, 0.1, -0.1, 0.0, 0.0, 0.0]),
    "wam_slot": (WAM_START, [0.0, 1.57, 1.57, 0.0, 0.0, 0.0, 0.0]),
    # Past the pillar: the WAM's arm reaching forward (elbow bent 1.5, hand 0.73 m from the first
    # axis) swings from one side to the other; the straight motion (the first joint alone, the
    # shortest) passes the hand 2 cm from the pillar, start and goal are 0.6 m from it.
    "wam_pillar": (WAM_PILLAR_START, [-0.9, 0.7, 0.0, 1.5, 0.0, 0.6, 0.0]),
    # Out of the cage between two bars and between the rings.
    "kr5_cage": (KR5_START, [0.0, 1.2, -1.1, 0.0, 0.0, 0.0]),
    "wam_cage": (WAM_START, [0.0, 1.6, 1.57, 0.0, 0.0, 0.0, 0.0]),
}


# ------------------------------------------------------------------------------------ geometry
def quat_from_rpy(roll, pitch, yaw):
    """URDF rpy (fixed axes x, then y, then z) as a quaternion (x, y, z, w)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def quat_rotate(q, v):
    x, y, z, w = q
    p = quat_mul(quat_mul(q, (v[0], v[1], v[2], 0.0)), (-x, -y, -z, w))
    return p[:3]


class Pose:
    """A rigid pose: position and quaternion (x, y, z, w)."""

    def __init__(self, position=(0.0, 0.0, 0.0), quaternion=(0.0, 0.0, 0.0, 1.0)):
        self.p = tuple(float(c) for c in position)
        self.q = quaternion

    def __mul__(self, other):
        r = quat_rotate(self.q, other.p)
        return Pose((self.p[0] + r[0], self.p[1] + r[1], self.p[2] + r[2]), quat_mul(self.q, other.q))


def yaw(angle):
    return quat_from_rpy(0.0, 0.0, angle)


AXIS_X = quat_from_rpy(0.0, math.pi / 2, 0.0)   # a cylinder's z axis turned onto x
AXIS_Y = quat_from_rpy(-math.pi / 2, 0.0, 0.0)  # ... onto y


class Scene:
    """Collision objects in the arm frame (lengths already scaled)."""

    def __init__(self):
        self.objects = []  # (id, object pose, [(primitive, pose)], [(mesh, pose)])

    def add(self, oid, pose=None, primitives=(), meshes=()):
        self.objects.append((oid, pose or Pose(), list(primitives), list(meshes)))

    def box(self, oid, centre, size, q=(0.0, 0.0, 0.0, 1.0)):
        self.add(oid, Pose(centre, q), [(("box", size), Pose())])


def wedge_mesh(length, width, height):
    """A closed triangular prism (a door wedge): 6 vertices, 8 triangles, centred on its base."""
    l, w = length / 2, width / 2
    v = [(-l, -w, 0), (l, -w, 0), (-l, -w, height), (-l, w, 0), (l, w, 0), (-l, w, height)]
    t = [(0, 2, 1), (3, 4, 5), (0, 1, 4), (0, 4, 3), (0, 3, 5), (0, 5, 2), (1, 2, 5), (1, 5, 4)]
    return v, t


# ------------------------------------------------------------------------------------ families
def table_pick(r):
    s = Scene()
    top_z, depth, width, t = 0.30 * r, 0.55 * r, 1.1 * r, 0.03
    cx = 0.62 * r
    legs = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            legs.append((("box", (0.04, 0.04, top_z - t)),
                         Pose((sx * (depth / 2 - 0.03), sy * (width / 2 - 0.03), -(top_z - t) / 2 - t / 2))))
    s.add("table", Pose((cx, 0.0, top_z - t / 2)), [(("box", (depth, width, t)), Pose())] + legs)
    s.add("can", Pose((cx - 0.12 * r, 0.28 * r, top_z + 0.06 * r)), [(("cylinder", (0.12 * r, 0.035 * r)), Pose())])
    s.add("bottle", Pose((cx + 0.15 * r, -0.22 * r, top_z + 0.1 * r)),
          [(("cylinder", (0.2 * r, 0.03 * r)), Pose()), (("sphere", (0.035 * r,)), Pose((0, 0, 0.1 * r)))])
    s.box("carton", (cx + 0.15 * r, 0.2 * r, top_z + 0.05 * r), (0.1 * r, 0.14 * r, 0.1 * r), yaw(0.4))
    s.add("wedge", Pose((cx - 0.1 * r, -0.3 * r, top_z), yaw(-0.3)),
          meshes=[(wedge_mesh(0.12 * r, 0.08 * r, 0.06 * r), Pose())])
    return s


def shelf(r):
    s = Scene()
    x0, depth, width, height, t = 0.62 * r, 0.32 * r, 1.0 * r, 1.5 * r, 0.02
    cx = x0 + depth / 2
    parts = [(("box", (depth, t, height)), Pose((0, sy * (width / 2 - t / 2), height / 2))) for sy in (-1, 1)]
    parts.append((("box", (t, width, height)), Pose((depth / 2 - t / 2, 0, height / 2))))
    for z in (0.02 * r, 0.42 * r, 0.78 * r, 1.14 * r, 1.5 * r - t / 2):
        parts.append((("box", (depth, width, t)), Pose((0, 0, z))))
    s.add("bookshelf", Pose((cx, 0.0, 0.0)), parts)
    s.box("book_a", (cx + 0.05 * r, -0.3 * r, 0.42 * r + t / 2 + 0.09 * r), (0.16 * r, 0.04 * r, 0.18 * r))
    s.box("book_b", (cx + 0.05 * r, -0.25 * r, 0.42 * r + t / 2 + 0.08 * r), (0.16 * r, 0.05 * r, 0.16 * r))
    s.add("jar", Pose((cx, 0.3 * r, 0.78 * r + t / 2 + 0.07 * r)), [(("cylinder", (0.14 * r, 0.05 * r)), Pose())])
    s.add("wedge", Pose((cx, 0.25 * r, 1.14 * r + t / 2), yaw(1.2)),
          meshes=[(wedge_mesh(0.12 * r, 0.08 * r, 0.06 * r), Pose())])
    return s


def open_box(r):
    s = Scene()
    cx, base_z = 0.6 * r, 0.18 * r
    inner_x, inner_y, wall_h, t = 0.36 * r, 0.5 * r, 0.3 * r, 0.02
    s.box("stand", (cx, 0.0, base_z / 2), (inner_x + 2 * t, inner_y + 2 * t, base_z))
    parts = [(("box", (inner_x + 2 * t, inner_y + 2 * t, t)), Pose((0, 0, t / 2)))]
    for sx in (-1, 1):
        parts.append((("box", (t, inner_y + 2 * t, wall_h)), Pose((sx * (inner_x / 2 + t / 2), 0, wall_h / 2))))
    for sy in (-1, 1):
        parts.append((("box", (inner_x, t, wall_h)), Pose((0, sy * (inner_y / 2 + t / 2), wall_h / 2))))
    s.add("bin", Pose((cx, 0.0, base_z)), parts)
    s.add("ball", Pose((cx + 0.08 * r, 0.12 * r, base_z + t + 0.05 * r)), [(("sphere", (0.05 * r,)), Pose())])
    s.add("wedge", Pose((cx - 0.06 * r, -0.14 * r, base_z + t), yaw(0.5)),
          meshes=[(wedge_mesh(0.12 * r, 0.08 * r, 0.06 * r), Pose())])
    return s


def cage(r):
    s = Scene()
    radius, height, bar = 0.78 * r, 1.5 * r, 0.015
    bars = []
    for k in range(12):
        a = 2 * math.pi * (k + 0.5) / 12
        bars.append((("cylinder", (height, bar)), Pose((radius * math.cos(a), radius * math.sin(a), height / 2))))
    # Two horizontal rings of bars (12-gons) at a third and two thirds of the height.
    side = 2 * radius * math.sin(math.pi / 12)
    for z in (height / 3, 2 * height / 3):
        for k in range(12):
            a = 2 * math.pi * k / 12
            c = radius * math.cos(math.pi / 12)
            bars.append((("cylinder", (side, bar)),
                         Pose((c * math.cos(a), c * math.sin(a), z), quat_mul(yaw(a), AXIS_Y))))
    s.add("cage", Pose(), bars)
    s.add("lamp", Pose((0.0, 0.0, height)), [(("sphere", (0.06 * r,)), Pose())])
    s.add("wedge", Pose((radius + 0.15 * r, 0.0, 0.0), yaw(0.0)),
          meshes=[(wedge_mesh(0.12 * r, 0.08 * r, 0.06 * r), Pose())])
    return s


def slot(r, gap, slot_z, wall_x):
    s = Scene()
    x, t, width, height = wall_x * r, 0.03, 1.2 * r, 1.3 * r
    slot_w = 0.5 * r
    lower = slot_z - gap / 2
    upper_h = height - (slot_z + gap / 2)
    side_w = (width - slot_w) / 2
    parts = [
        (("box", (t, width, lower)), Pose((0, 0, lower / 2))),
        (("box", (t, width, upper_h)), Pose((0, 0, slot_z + gap / 2 + upper_h / 2))),
    ]
    for sy in (-1, 1):
        parts.append((("box", (t, side_w, gap)), Pose((0, sy * (slot_w / 2 + side_w / 2), slot_z))))
    s.add("wall", Pose((x, 0.0, 0.0)), parts)
    s.box("shelf_behind", (x + 0.25 * r, 0.0, slot_z - gap / 2 - 0.06), (0.3 * r, 0.6 * r, 0.02))
    s.add("wedge", Pose((x + 0.25 * r, 0.2 * r, slot_z - gap / 2 - 0.05), yaw(0.0)),
          meshes=[(wedge_mesh(0.1 * r, 0.06 * r, 0.05 * r), Pose())])
    return s


def pillar(r, distance):
    """A pillar the arm's straight swing grazes (clearance-optimal planning: the shortest path passes
    close, others keep away), a ball on it, a crate behind with a wedge on it."""
    s = Scene()
    radius, height = 0.04, 1.5 * r
    s.add("pillar", Pose((distance, 0.0, 0.0)),
          [(("cylinder", (height, radius)), Pose((0, 0, height / 2))), (("sphere", (0.06 * r,)), Pose((0, 0, height)))])
    s.box("crate", (-0.9 * r, -0.9 * r, 0.1 * r), (0.3 * r, 0.3 * r, 0.2 * r), yaw(0.3))
    s.add("wedge", Pose((-0.9 * r, -0.9 * r, 0.2 * r), yaw(0.3)),
          meshes=[(wedge_mesh(0.12 * r, 0.08 * r, 0.06 * r), Pose())])
    return s


FAMILIES = {
    "table_pick": ("a table with a can, a bottle, a carton and a wedge on it", table_pick),
    "shelf": ("a bookshelf of four boards with books, a jar and a wedge", shelf),
    "box": ("an open bin on a stand, with a ball and a wedge inside", open_box),
    "cage": ("twelve bars and two rings around the arm, a lamp above", cage),
    "slot": ("a wall with a narrow horizontal slot, a shelf behind it", None),
    "pillar": ("a pillar the straight swing grazes, a crate behind", None),
}
# The slot per robot: its height (metres), about 1.5 times the thickness of the forearm that
# passes it; the height of its middle (metres), where the forearm lies when the arm reaches
# straight forward (the KR5's at 0.69 with the upper arm upright, the WAM's at its shoulder with
# the upper arm straight forward); and the wall's distance from the first axis (in reaches).
# The WAM's wall stands at 0.65, just beyond its upper arm (0.61 m from the shoulder with its
# housing): at 0.5, as first written, the elbow would have to cross the wall, where the sphere it
# moves on (0.55 m about the shoulder) meets the wall's plane at 0.2-0.26 m from the slot's
# middle, at the slot's edges, with the upper arm's 10 cm housing around it; the goal lay in a
# pocket no motion from the start reaches (problems/arm/README.md).
SLOT = {"kr5": (0.22, 0.69, 0.5), "wam": (0.22, 0.346, 0.65)}


# ------------------------------------------------------------------------------------- writing
def num(x):
    """A number as YAML text: 17 significant digits at most, no exponent for ordinary values."""
    x = float(x)
    if x == 0.0:
        return "0"
    text = repr(round(x, 12))
    return text[:-2] if text.endswith(".0") else text


def point(p):
    return "{x: %s, y: %s, z: %s}" % tuple(num(c) for c in p)


def quaternion(q):
    return "{x: %s, y: %s, z: %s, w: %s}" % tuple(num(c) for c in q)


def scene_yaml(name, scene, mount, robot):
    world_t_arm = Pose(mount[0], quat_from_rpy(*mount[1]))
    lines = ["# Written by problems/arm/make_arm_problems.py: %s, %s." % (name, robot),
             "# Poses in the URDF's world frame; see problems/arm/README.md.",
             "name: %s" % name, "world:", "  collision_objects:"]
    for oid, pose, primitives, meshes in scene.objects:
        world = world_t_arm * pose
        lines += ["    - id: %s" % oid, "      header:", "        frame_id: world", "      pose:",
                  "        position: %s" % point(world.p), "        orientation: %s" % quaternion(world.q)]
        if primitives:
            lines.append("      primitives:")
            for (kind, dims), _ in primitives:
                lines.append("        - type: %s" % kind)
                lines.append("          dimensions: [%s]" % ", ".join(num(d) for d in dims))
            lines.append("      primitive_poses:")
            for _, p in primitives:
                lines += ["        - position: %s" % point(p.p), "          orientation: %s" % quaternion(p.q)]
        if meshes:
            lines.append("      meshes:")
            for (vertices, triangles), _ in meshes:
                lines.append("        - vertices:")
                lines += ["            - %s" % point(v) for v in vertices]
                lines.append("          triangles:")
                lines += ["            - vertex_indices: [%d, %d, %d]" % t for t in triangles]
            lines.append("      mesh_poses:")
            for _, p in meshes:
                lines += ["        - position: %s" % point(p.p), "          orientation: %s" % quaternion(p.q)]
    return "\n".join(lines) + "\n"


def request_yaml(name, robot, start, goal):
    joints = ROBOTS[robot]["joints"]
    lines = ["# Written by problems/arm/make_arm_problems.py: %s." % name,
             "group_name: %s" % ROBOTS[robot]["group"],
             "num_planning_attempts: 1",
             "allowed_planning_time: 10",
             "start_state:",
             "  joint_state:",
             "    header: {frame_id: world}",
             "    name: [%s]" % ", ".join("'%s'" % j for j in joints),
             "    position: [%s]" % ", ".join(num(q) for q in start),
             "goal_constraints:",
             "  - joint_constraints:"]
    for j, q in zip(joints, goal):
        lines += ["      - joint_name: '%s'" % j, "        position: %s" % num(q),
                  "        tolerance_above: 0.001", "        tolerance_below: 0.001", "        weight: 1"]
    return "\n".join(lines) + "\n"


def problem_cfg(name, robot, description):
    return "\n".join(
        [
        "# %s: %s (problems/arm/README.md)." % (name, description),
        "# The robot comes from Debian's dart-doc: problems/data/fetch_robots.sh fills ${ADSD_ROBOTS}",
        "# (default ~/.cache/adsd/robots).",
        "[problem]",
        "name = %s" % name,
        "robot = %s" % ROBOTS[robot]["urdf"]]
        + (["srdf = %s" % ROBOTS[robot]["srdf"]] if "srdf" in ROBOTS[robot] else [])
        + ["scene = scene.yaml",
        "request = request.yaml",
        "package_path = ${ADSD_ROBOTS}",
        ""])


def check_limits(name, robot, vector):
    joints, limits = ROBOTS[robot]["joints"], LIMITS[robot]
    if len(vector) != len(joints):
        sys.exit("make_arm_problems.py: %s: %d values for %d joints" % (name, len(vector), len(joints)))
    for j, q, (lo, hi) in zip(joints, vector, limits):
        if not lo <= q <= hi:
            sys.exit("make_arm_problems.py: %s: joint %s = %g is outside [%g, %g]" % (name, j, q, lo, hi))


# The pillar's axis from the first joint's axis (metres): the hand's reach in the swing (0.73 m for
# the WAM's pose above) plus 2 cm plus the pillar's radius.
PILLAR = {"wam": 0.79}


def build_scene(robot, family):
    r = ROBOTS[robot]["reach"]
    if family == "slot":
        return slot(r, *SLOT[robot])
    if family == "pillar":
        return pillar(r, PILLAR[robot])
    return FAMILIES[family][1](r)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    args = parser.parse_args()
    written = 0
    for robot in ROBOTS:
        for family, (description, _) in FAMILIES.items():
            name = "%s_%s" % (robot, family)
            if name not in GOALS:
                continue
            start, goal = GOALS[name]
            check_limits(name, robot, start)
            check_limits(name, robot, goal)
            directory = os.path.join(args.out, name)
            os.makedirs(directory, exist_ok=True)
            files = {"scene.yaml": scene_yaml(name, build_scene(robot, family), ROBOTS[robot]["mount"], robot),
                     "request.yaml": request_yaml(name, robot, start, goal),
                     "problem.cfg": problem_cfg(name, robot, description)}
            for file_name, text in files.items():
                with open(os.path.join(directory, file_name), "w", encoding="utf-8") as out:
                    out.write(text)
            written += 1
    print("make_arm_problems.py: %d problems written to %s" % (written, args.out))


if __name__ == "__main__":
    main()
