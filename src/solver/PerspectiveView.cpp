#include "src/solver/PerspectiveView.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

#include "gl/Debug.h"
#include "gl/Shader.h"
#include "gl/State.h"
#include "src/base/Error.h"

namespace hemirad {

namespace {
constexpr std::size_t kVec4 = 4 * sizeof(float);
constexpr unsigned kFirstEpochs = 4;
}  // namespace

PerspectiveView::PerspectiveView(const SolverState& state, std::size_t blockCount, unsigned decayShots, double interest,
                                 int resolution)
    : state_(state),
      blocks_(blockCount),
      surfaces_(state.scene.polygons().size()),
      decayShots_(std::max(1u, decayShots)),
      byImportance_(interest > 0),
      resolution_(resolution),
      mesh_(state.scene, state.atlas),
      ids_(gl::renderProgram("camera.vert", "view_id.frag")),
      seenPass_(gl::computeProgram("view_surfaces.comp")),
      importantPass_(gl::computeProgram("important_surfaces.comp")),
      pendingPass_(gl::computeProgram("pending_blocks.comp")),
      deferredPass_(gl::computeProgram("deferred_shooters.comp")),
      surfaceView_(surfaces_ * 2 * sizeof(std::uint32_t)),
      shotSoFar_(blocks_ * kVec4),
      seen_(surfaces_ * sizeof(std::uint32_t)),
      pending_(blocks_ * sizeof(std::uint32_t)),
      deferredBlocks_(blocks_ * sizeof(std::uint32_t)),
      visible_(surfaces_, 1),
      epoch_(surfaces_, -1) {
  shotSoFar_.clear(0.0f);
  pendingPass_.set("blockCount", unsigned(blocks_));
  double area = 0;
  for (const auto& pa : state.atlas.positionArea) area += pa.w;
  importantPass_.set("threshold", float(interest / area));
  uploadSurfaces(false);
}

double PerspectiveView::simulatedFov() const {
  return camera_.fovY + (180.0 - camera_.fovY) * double(std::min(step_, kSteps)) / kSteps;
}

std::size_t PerspectiveView::surfacesInView() const { return std::size_t(std::count(visible_.begin(), visible_.end(), 1)); }

void PerspectiveView::look(const Camera& camera, double aspect, unsigned shots) {
  if (looked_ && camera == camera_ && aspect == aspect_) return;
  looked_ = true;
  camera_ = camera;
  aspect_ = aspect;
  lookShots_ = shots;
  step_ = 0;
  pending_view_ = true;
}

unsigned PerspectiveView::shotsToNextStep(unsigned shots) const {
  if (wholeScene()) return kNoStep;
  const unsigned at = lookShots_ + unsigned(std::uint64_t(decayShots_) * unsigned(step_ + 1) / kSteps);
  return at > shots ? at - shots : 0;
}

void PerspectiveView::grow(unsigned shots) {
  int step = step_;
  while (step < kSteps &&
         shots >= lookShots_ + unsigned(std::uint64_t(decayShots_) * unsigned(step + 1) / kSteps))
    ++step;
  if (step == step_) return;
  step_ = step;
  pending_view_ = true;
}

void PerspectiveView::showAll() {
  step_ = kSteps;
  pending_view_ = true;
}

bool PerspectiveView::update() {
  if (!pending_view_ || delivering_) return false;
  pending_view_ = false;
  applyView();
  delivering_ = true;
  if (deferred_ == 0) finishDeliveries();  // nothing to deliver: the change is complete
  return true;
}

// Seed 004 §5.3: the surfaces with a pixel in a view of the simulated field of view, and those
// whose light the view needs (importance above the interest threshold, important_surfaces.comp).
std::vector<std::uint8_t> PerspectiveView::renderSeen() {
  const int w = aspect_ >= 1 ? resolution_ : std::max(1, int(std::lround(resolution_ * aspect_)));
  const int h = aspect_ >= 1 ? std::max(1, int(std::lround(resolution_ / aspect_))) : resolution_;
  gl::Texture ids(GL_R32UI, w, h), depth(GL_DEPTH_COMPONENT32F, w, h);
  gl::Framebuffer fbo;
  fbo.attach(GL_COLOR_ATTACHMENT0, ids);
  fbo.attach(GL_DEPTH_ATTACHMENT, depth);
  fbo.checkComplete("perspective view");
  fbo.clearColor(0xFFFFFFFFu);
  fbo.clearDepth(0.0f);  // reversed depth: 0 is infinitely far
  seen_.clear(0u);

  Camera wide = camera_;
  wide.fovY = std::min(simulatedFov(), 179.0);
  glm::mat4 vp = mesh_.viewProjection(wide, aspect_);
  fbo.bind();
  gl::cameraView(w, h).apply();
  ids_.set("viewProjection", &vp[0][0]);
  ids_.use();
  mesh_.draw();
  gl::barrier(gl::Barrier::Image | gl::Barrier::Framebuffer);

  ids.bindImage(0, GL_READ_ONLY);
  seen_.bindBase(GL_SHADER_STORAGE_BUFFER, 9);
  seenPass_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(w), 16), gl::groupsFor(unsigned(h), 16));
  gl::barrier(gl::Barrier::Storage);
  if (byImportance_) {
    state_.bindScene();
    state_.radiosity.bindImage(0, GL_READ_ONLY);
    importantPass_.use();
    gl::Program::dispatch(gl::groupsFor(unsigned(state_.atlas.width), 16), gl::groupsFor(unsigned(state_.atlas.height), 16));
  }
  gl::barrier(gl::Barrier::BufferUpdate);
  std::vector<std::uint32_t> seen(surfaces_);
  seen_.read(0, seen.size() * sizeof(std::uint32_t), seen.data());
  return {seen.begin(), seen.end()};
}

// A snapshot slot for surfaces leaving the view now. With all slots taken, the oldest epoch's
// surfaces receive their entries now and join the new epoch (its snapshot is taken after).
unsigned PerspectiveView::takeEpoch(const std::vector<std::uint8_t>& seen) {
  for (unsigned e = 0; e < capacity_; ++e)
    if (!epochBirth_[e]) return epochBirth_[e] = ++births_, e;
  if (capacity_ < kMaxEpochs) {
    const unsigned grown = std::min(kMaxEpochs, std::max(kFirstEpochs, 2 * capacity_));
    gl::Buffer bigger(std::size_t(grown) * blocks_ * kVec4);
    if (capacity_) snapshots_.copyTo(bigger, 0, 0, std::size_t(capacity_) * blocks_ * kVec4);
    snapshots_ = std::move(bigger);
    epochBirth_.resize(grown, 0);
    const unsigned e = capacity_;
    capacity_ = grown;
    return epochBirth_[e] = ++births_, e;
  }
  const unsigned oldest = unsigned(std::min_element(epochBirth_.begin(), epochBirth_.end()) - epochBirth_.begin());
  for (std::uint32_t p = 0; p < surfaces_; ++p)
    if (epoch_[p] == int(oldest) && !visible_[p] && !seen[p]) entering_.push_back(p), staysOut_.push_back(1);
  epochBirth_[oldest] = ++births_;
  return oldest;
}

void PerspectiveView::applyView() {
  std::vector<std::uint8_t> seen = wholeScene() ? std::vector<std::uint8_t>(surfaces_, 1) : renderSeen();
  entering_.clear();
  staysOut_.clear();
  newEpoch_ = -1;
  for (std::uint32_t p = 0; p < surfaces_; ++p)
    if (!visible_[p] && seen[p]) entering_.push_back(p), staysOut_.push_back(0);
  for (std::uint32_t p = 0; p < surfaces_; ++p)
    if (visible_[p] && !seen[p]) {
      if (newEpoch_ < 0) newEpoch_ = int(takeEpoch(seen));
      epoch_[p] = newEpoch_;
    }
  visible_ = seen;

  // Seed 004 §5.5.2: the shooting locations of the entries to deliver, in block order.
  deferred_ = next_ = 0;
  if (entering_.empty()) return uploadSurfaces(false);
  std::vector<GLuint> epochs;
  for (std::uint32_t p : entering_)
    if (std::find(epochs.begin(), epochs.end(), GLuint(epoch_[p])) == epochs.end()) epochs.push_back(GLuint(epoch_[p]));
  pendingPass_.set("epochCount", unsigned(epochs.size()));
  pendingPass_.set("epochs", std::span<const unsigned>(epochs));
  bind();
  pending_.bindBase(GL_SHADER_STORAGE_BUFFER, 9);
  pendingPass_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(blocks_), 256));
  gl::barrier(gl::Barrier::BufferUpdate);
  std::vector<std::uint32_t> pending(blocks_), list;
  pending_.read(0, pending.size() * sizeof(std::uint32_t), pending.data());
  for (std::uint32_t b = 0; b < blocks_; ++b)
    if (pending[b]) list.push_back(b);
  if (!list.empty()) deferredBlocks_.upload(0, list.size() * sizeof(std::uint32_t), list.data());
  deferred_ = list.size();
  uploadSurfaces(true);
}

void PerspectiveView::describeDeliveries(unsigned count, const gl::Buffer& nodes, const gl::Buffer& control) {
  count = unsigned(std::min<std::size_t>(count, deliveriesLeft()));
  state_.bindScene();
  nodes.bindBase(GL_SHADER_STORAGE_BUFFER, 13);
  control.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  deferredBlocks_.bindBase(GL_SHADER_STORAGE_BUFFER, 9);
  deferredPass_.set("first", unsigned(next_));
  deferredPass_.set("count", count);
  deferredPass_.use();
  gl::Program::dispatch(gl::groupsFor(count, 64));
  gl::barrier(gl::Barrier::Storage | gl::Barrier::Command);
  next_ += count;
}

void PerspectiveView::finishDeliveries() {
  for (std::size_t k = 0; k < entering_.size(); ++k) epoch_[entering_[k]] = staysOut_[k] ? newEpoch_ : -1;
  // Free the slots nobody refers to any more, then snapshot the new epoch (delivery passes do
  // not shoot, so shots so far are as they were when the surfaces left).
  for (unsigned e = 0; e < capacity_; ++e)
    if (epochBirth_[e] && int(e) != newEpoch_ && std::find(epoch_.begin(), epoch_.end(), int(e)) == epoch_.end())
      epochBirth_[e] = 0;
  gl::barrier(gl::Barrier::BufferUpdate);
  if (newEpoch_ >= 0) shotSoFar_.copyTo(snapshots_, 0, std::size_t(newEpoch_) * blocks_ * kVec4, blocks_ * kVec4);
  entering_.clear();
  staysOut_.clear();
  newEpoch_ = -1;
  deferred_ = next_ = 0;
  delivering_ = false;
  uploadSurfaces(false);
  gl::checkErrors("perspective view");
}

// x: in view; y: 1 + the epoch of the entries a surface receives in this change's deliveries.
void PerspectiveView::uploadSurfaces(bool delivering) {
  std::vector<std::uint32_t> v(surfaces_ * 2, 0);
  for (std::size_t p = 0; p < surfaces_; ++p) v[2 * p] = visible_[p];
  if (delivering)
    for (std::uint32_t p : entering_) v[2 * p + 1] = std::uint32_t(epoch_[p] + 1);
  surfaceView_.upload(0, v.size() * sizeof(std::uint32_t), v.data());
}

void PerspectiveView::bind() const {
  surfaceView_.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
  shotSoFar_.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  if (snapshots_) snapshots_.bindBase(GL_SHADER_STORAGE_BUFFER, 8);
  else shotSoFar_.bindBase(GL_SHADER_STORAGE_BUFFER, 8);  // no epoch yet: never read, but bound
}

}  // namespace hemirad

namespace hemirad {

namespace {

// Plain little-endian-as-in-memory fields, in a fixed order (checkpoints stay on one machine kind).
struct Writer {
  std::vector<std::uint8_t> bytes;
  template <class T> void put(const T& v) { putBytes(&v, sizeof v); }
  template <class T> void putVector(const std::vector<T>& v) {
    put(std::uint64_t(v.size()));
    putBytes(v.data(), v.size() * sizeof(T));
  }
  void putBytes(const void* p, std::size_t n) {
    if (n) bytes.insert(bytes.end(), static_cast<const std::uint8_t*>(p), static_cast<const std::uint8_t*>(p) + n);
  }
};

struct Reader {
  std::span<const std::uint8_t> bytes;
  std::size_t at = 0;
  void getBytes(void* p, std::size_t n) {
    if (n > bytes.size() - at) throw InputError("checkpoint: perspective view state is corrupt");
    if (n) std::memcpy(p, bytes.data() + at, n);
    at += n;
  }
  template <class T> T get() {
    T v;
    getBytes(&v, sizeof v);
    return v;
  }
  template <class T> std::vector<T> getVector(std::size_t most) {
    const auto n = get<std::uint64_t>();
    if (n > most) throw InputError("checkpoint: perspective view state is corrupt");
    std::vector<T> v(n);
    getBytes(v.data(), n * sizeof(T));
    return v;
  }
};

}  // namespace

std::vector<std::uint8_t> PerspectiveView::save() const {
  Writer w;
  w.put(std::uint64_t(blocks_)), w.put(std::uint64_t(surfaces_));
  w.put(camera_), w.put(aspect_), w.put(lookShots_), w.put(looked_), w.put(step_);
  w.put(pending_view_), w.put(delivering_), w.put(newEpoch_), w.put(std::uint64_t(deferred_)), w.put(std::uint64_t(next_));
  w.put(births_), w.put(capacity_);
  w.putVector(visible_), w.putVector(epoch_), w.putVector(epochBirth_), w.putVector(entering_), w.putVector(staysOut_);
  std::vector<glm::vec4> table(blocks_ * (1 + std::size_t(capacity_)));
  shotSoFar_.read(0, blocks_ * kVec4, table.data());
  if (capacity_) snapshots_.read(0, std::size_t(capacity_) * blocks_ * kVec4, table.data() + blocks_);
  w.putVector(table);
  std::vector<std::uint32_t> deferred(deferred_);
  if (deferred_) deferredBlocks_.read(0, deferred_ * sizeof(std::uint32_t), deferred.data());
  w.putVector(deferred);
  return std::move(w.bytes);
}

void PerspectiveView::restore(std::span<const std::uint8_t> bytes) {
  Reader r{bytes};
  if (r.get<std::uint64_t>() != blocks_ || r.get<std::uint64_t>() != surfaces_)
    throw InputError("checkpoint: perspective view state is of another scene");
  camera_ = r.get<Camera>(), aspect_ = r.get<double>(), lookShots_ = r.get<unsigned>(), looked_ = r.get<bool>();
  step_ = r.get<int>(), pending_view_ = r.get<bool>(), delivering_ = r.get<bool>(), newEpoch_ = r.get<int>();
  deferred_ = std::size_t(r.get<std::uint64_t>()), next_ = std::size_t(r.get<std::uint64_t>());
  births_ = r.get<std::uint64_t>(), capacity_ = r.get<unsigned>();
  visible_ = r.getVector<std::uint8_t>(surfaces_), epoch_ = r.getVector<int>(surfaces_);
  epochBirth_ = r.getVector<std::uint64_t>(kMaxEpochs);
  entering_ = r.getVector<std::uint32_t>(surfaces_), staysOut_ = r.getVector<std::uint8_t>(surfaces_);
  const std::vector<glm::vec4> table = r.getVector<glm::vec4>(blocks_ * (1 + kMaxEpochs));
  const std::vector<std::uint32_t> deferred = r.getVector<std::uint32_t>(blocks_);
  if (r.at != bytes.size() || visible_.size() != surfaces_ || epoch_.size() != surfaces_ ||
      epochBirth_.size() != capacity_ || table.size() != blocks_ * (1 + std::size_t(capacity_)) ||
      deferred.size() != deferred_ || next_ > deferred_ || staysOut_.size() != entering_.size())
    throw InputError("checkpoint: perspective view state is corrupt");
  shotSoFar_.upload(0, blocks_ * kVec4, table.data());
  snapshots_ = capacity_ ? gl::Buffer(std::size_t(capacity_) * blocks_ * kVec4) : gl::Buffer();
  if (capacity_) snapshots_.upload(0, std::size_t(capacity_) * blocks_ * kVec4, table.data() + blocks_);
  if (deferred_) deferredBlocks_.upload(0, deferred_ * sizeof(std::uint32_t), deferred.data());
  uploadSurfaces(delivering_);
}

}  // namespace hemirad
