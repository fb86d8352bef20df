// Counter-based random numbers: a PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU
// Rendering") chained over the key, so a draw depends only on (seed, iteration, shooter,
// level) and never on scheduling, the batch or the backend.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Uniform in [0, 1), 24 bits (exact in a float).
float uniformDraw(uint seed, uint iteration, uint shooter, uint level) {
  uint h = pcgHash(pcgHash(pcgHash(pcgHash(seed) + iteration) + shooter) + level);
  return float(h >> 8u) * (1.0 / 16777216.0);
}
