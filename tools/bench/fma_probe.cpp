// Kept in its own file so the compiler cannot see the arguments and fold the expression: what
// runs is what the build flags made of `a * b + c` (two roundings under -ffp-contract=off, one
// fused rounding if contraction were on and the target had FMA).
#include "bench/accuracy.h"

namespace rt::bench {

float multiply_add(float a, float b, float c) {
    return a * b + c;
}
double multiply_add(double a, double b, double c) {
    return a * b + c;
}

}  // namespace rt::bench
