// Exits 0 when the CPU running the build has the fma instruction.
int main() { return __builtin_cpu_supports("fma") ? 0 : 1; }
