// Shared by the bad-input tests (docs/errors.md, one TEST_CASE per row): each bad input gives
// exactly one `hemirad: error:` line naming the file and line (scene content) or the flag, exit
// code 2, and leaves nothing in the output folder.
#pragma once
#include <string>
#include <vector>

namespace hemirad::test::bad_input {

// Every output flag, into a fresh folder that must still be empty afterwards (no output, no
// temporary file).
struct Outputs {
  std::string dir, flags;
  explicit Outputs(const std::string& name);
  bool empty() const;
};

// `hemirad ARGS` with every output flag: exit code 2, exactly one error line holding every one
// of `messages`, no output written.
void expectRefused(const std::string& name, const std::string& args, const std::vector<std::string>& messages,
                   const std::string& env = "");

inline const std::string kMtl = "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\nnewmtl grey\nKd 0.5 0.5 0.5\n";
// Lines 1-6; a face on line 7 follows.
inline const std::string kQuad = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl lamp\n";

// Writes s.obj and m.mtl into a fresh folder; returns the OBJ's path.
std::string writeScene(const std::string& name, const std::string& obj, const std::string& mtl = kMtl);

inline std::string solve(const std::string& obj) { return "solve " + obj + " --shots 2 --quiet"; }

}  // namespace hemirad::test::bad_input
