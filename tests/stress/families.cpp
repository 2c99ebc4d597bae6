#include "families.h"

#include <cmath>

namespace adsd::stress {

const std::vector<Family>& families() {
  static const std::vector<Family> all = [] {
    std::vector<Family> f = triangleFamilies();
    std::vector<Family> m = meshFamilies();
    f.insert(f.end(), m.begin(), m.end());
    return f;
  }();
  return all;
}

const Family* findFamily(const std::string& name) {
  for (const Family& f : families()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

namespace {

/// splitmix64: a bijective mixer, so distinct (seed, family, index) give unrelated streams.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// FNV-1a of the family's name: the family's stream does not depend on its place in the list.
std::uint64_t nameHash(const std::string& name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : name) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

}  // namespace

StressCase generateCase(const Family& family, std::uint64_t seed, std::uint64_t index, double fixedScale) {
  SeededRandom random(mix(mix(seed ^ nameHash(family.name)) + index));
  const double scale = fixedScale > 0 ? fixedScale : random.logUniform(family.log10ScaleLo, family.log10ScaleHi);
  Generated g = family.generate(random, scale);
  return StressCase{family.name, seed, index, scale, g.variant, g.penetrating, std::move(g.a), std::move(g.b), g.poseA, g.poseB};
}

}  // namespace adsd::stress
