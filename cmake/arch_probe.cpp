// Configure-time probe: compiled with the candidate -march flag and run; it
// exits 0 only if the machine executes the vector and FMA instructions that
// flag lets the compiler use, at the widest vector the engine's ray lanes
// take under it (engine/core/lanes.hpp: 64 bytes with AVX-512).
#include <cmath>
#include <cstdio>

typedef double Wide __attribute__((vector_size(64)));

int main() {
  volatile double a = 1.5, b = 2.25, c = 0.125;
  double v[8];
  for (int i = 0; i < 8; ++i) v[i] = std::fma(a * i, b, c);  // FMA + vectorised loop
  Wide w = {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
  w = w * w + w;  // one register wide where AVX-512 is on
  double s = 0;
  for (int i = 0; i < 8; ++i) s += w[i];
  return s > 0 ? 0 : 1;
}
