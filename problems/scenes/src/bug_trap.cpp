#include "adsd/problem_scenes.h"
#include "scene_parts.h"

namespace adsd::shapes {

// A closed cube (inside half-size 2.5, walls 0.2 thick) whose +x wall has a 1 m square hole, from
// which a square funnel (inside 1 × 1) reaches 1.3 m inwards: the classic trap, easy to enter and
// hard to leave. The robot is a rod (capsule of radius 0.12, 1.24 m long) starting inside at
// (-1, 0, 0); the goal is outside at (4.5, 0, 0).
ProblemScene bugTrapScene() {
  constexpr double h = 2.5, t = 0.2, hole = 0.5, funnelEnd = 1.2;
  SceneParts parts;
  // -x, ±y, ±z walls.
  parts.addBox(Vec3(-h - t, -h - t, -h - t), Vec3(-h, h + t, h + t));
  parts.addBox(Vec3(-h, -h - t, -h - t), Vec3(h + t, -h, h + t));
  parts.addBox(Vec3(-h, h, -h - t), Vec3(h + t, h + t, h + t));
  parts.addBox(Vec3(-h, -h, -h - t), Vec3(h + t, h, -h));
  parts.addBox(Vec3(-h, -h, h), Vec3(h + t, h, h + t));
  // +x wall with the square hole: four slabs around it.
  parts.addBox(Vec3(h, -h, hole), Vec3(h + t, h, h));
  parts.addBox(Vec3(h, -h, -h), Vec3(h + t, h, -hole));
  parts.addBox(Vec3(h, -h, -hole), Vec3(h + t, -hole, hole));
  parts.addBox(Vec3(h, hole, -hole), Vec3(h + t, h, hole));
  // The funnel: four plates from the hole inwards.
  parts.addBox(Vec3(funnelEnd, -hole - t, -hole - t), Vec3(h, hole + t, -hole));
  parts.addBox(Vec3(funnelEnd, -hole - t, hole), Vec3(h, hole + t, hole + t));
  parts.addBox(Vec3(funnelEnd, -hole - t, -hole), Vec3(h, -hole, hole));
  parts.addBox(Vec3(funnelEnd, hole, -hole), Vec3(h, hole + t, hole));
  return {"bug_trap", {centredOnVertexMean(capsule(0.12, 0.5, 16))}, parts.merged()};
}

}  // namespace adsd::shapes
