// Configure-time probe: compiled with the candidate -march flag and run; it
// exits 0 only if the machine executes the vector and FMA instructions that
// flag lets the compiler use.
#include <cmath>
#include <cstdio>

int main() {
  volatile double a = 1.5, b = 2.25, c = 0.125;
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = std::fma(a * i, b, c);  // FMA + vectorised loop
  double s = 0;
  for (double x : v) s += x;
  return s > 0 ? 0 : 1;
}
