// Compiled with -ffast-math by the CTest install.fast_math_refused: the
// public header must stop the build with its #error.
#include "sillage/sillage.h"

int main() { return (sillage::Interval(0.1) + sillage::Interval(0.2)).contains(0.3) ? 0 : 1; }
