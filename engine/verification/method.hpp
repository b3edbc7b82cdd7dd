// The numerical method a known-answer problem runs with: transfer scheme, shape function and
// precision. `firn verify` uses the defaults (APIC/MLS, quadratic B-splines, double); `firn study
// accuracy` varies all three at a problem's fixed CFL number.
#pragma once

#include <string>

#include "kernels/shape_functions.hpp"
#include "kernels/transfer.hpp"

namespace firn {

enum class Precision { single, double_ };

struct VerificationMethod {
  Transfer transfer = Transfer::apic;
  Shape shape = Shape::quadratic;
  Precision precision = Precision::double_;
};

inline const char* transfer_name(Transfer t) {
  return t == Transfer::apic ? "apic" : t == Transfer::pic ? "pic" : "flip";
}
inline const char* shape_name(Shape s) { return s == Shape::quadratic ? "quadratic" : "cubic"; }
inline const char* precision_name(Precision p) { return p == Precision::single ? "float" : "double"; }

// "apic/quadratic/double"
inline std::string method_name(const VerificationMethod& m) {
  return std::string(transfer_name(m.transfer)) + "/" + shape_name(m.shape) + "/" + precision_name(m.precision);
}

// Calls run(T{}) with T the method's scalar type, float or double.
template <class Run>
auto with_precision(const VerificationMethod& m, Run&& run) {
  return m.precision == Precision::single ? run(float{}) : run(double{});
}

}  // namespace firn
