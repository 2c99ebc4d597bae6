#pragma once
// A shared pointer a constructor is handed, checked before anything reads through it: a null
// scene or checker is the caller's mistake, reported as one, not a crash (an outside review:
// MeshValidityChecker(si, nullptr) and CertifiedMotionValidator(si, nullptr) died of SIGSEGV).

#include <memory>
#include <string>
#include <utility>

#include "adsd/error.h"

namespace adsd::planner::detail {

template <class T>
std::shared_ptr<T> nonNull(std::shared_ptr<T> pointer, const std::string& what) {
  if (!pointer) throw InputError(what + " is null");
  return pointer;
}

}  // namespace adsd::planner::detail
