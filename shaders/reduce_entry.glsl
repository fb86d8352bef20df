// One entry of the shooter reduction: the best block so far and the running unshot sum.
struct Entry {
  float best;   // largest power
  uint index;   // its block; ties go to the lower index, so the choice is deterministic
  float sum;    // total unshot power (for convergence)
  float pad;
};

Entry combine(Entry a, Entry b) {
  bool takeB = b.best > a.best || (b.best == a.best && b.index < a.index);
  return Entry(takeB ? b.best : a.best, takeB ? b.index : a.index, a.sum + b.sum, 0.0);
}
