#include "src/reference/ReferenceCommand.h"

#include <fmt/format.h>

#include <filesystem>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/base/OutputPaths.h"
#include "src/output/ImageFile.h"
#include "src/reference/ErrorTable.h"
#include "src/reference/PixelRegions.h"
#include "src/scene/Camera.h"

namespace hemirad {

namespace {

Image readSized(const std::string& path, const std::string& what, int width, int height) {
  Image image = readImage(path);
  if (width && (image.width != width || image.height != height))
    throw InputError(fmt::format("{} ({}) is {} x {} pixels, the images compared {} x {}", what, path, image.width,
                                 image.height, width, height));
  return image;
}

}  // namespace

ReferenceWriters imageFileWriters() { return {{".exr", ".png"}, {".exr"}, {".png"}, encodeRender, encodeExr}; }

int runCompare(const CompareOptions& o) {
  for (const std::string& path : {o.a, o.b, o.standardError}) {  // a PNG holds tone-mapped, not linear, light
    const std::string ext = std::filesystem::path(path).extension().string();
    if (!path.empty() && ext != ".exr" && ext != ".pfm")
      throw InputError(path +
                       ": compare reads linear EXR or PFM images (solve --out X.exr, reference --out X.exr, "
                       "hemirad-bench reference --out X.pfm)");
  }
  std::vector<OutputPath> outputs;
  if (!o.errorMap.empty()) outputs.push_back({"--error-map", o.errorMap, {".png"}});
  if (!o.markdownOut.empty()) outputs.push_back({"--markdown", o.markdownOut, {".md"}, true});
  std::vector<InputPath> inputs{{"image A", o.a}, {"image B", o.b}, {"the scene", o.scene}};
  if (!o.standardError.empty()) inputs.push_back({"B's standard error (--stderr)", o.standardError});
  checkOutputs(outputs, inputs);
  const Image a = readImage(o.a);
  const Image b = readSized(o.b, "image B", a.width, a.height);
  const Image se = o.standardError.empty() ? Image{} : readSized(o.standardError, "--stderr", a.width, a.height);
  const Scene scene = loadScene(o.scene, o.load);
  const PixelRegions regions = pixelRegions(scene, resolveCamera(scene, o.camera), a.width, a.height);
  const std::string table = markdown(errorTable(scene, regions, a, b, se));
  OutputBatch files;
  if (!o.errorMap.empty()) files.add("--error-map", o.errorMap, encodePng(errorMap(regions, a, b, o.errorRange), 1.0));
  if (!o.markdownOut.empty()) files.add("--markdown", o.markdownOut, table);
  files.commit();
  if (o.markdownOut != "-") fmt::print("{}", table);  // `--markdown -` has printed it already
  return 0;
}

}  // namespace hemirad
