#include "src/solver/PerspectiveView.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl/Debug.h"
#include "gl/Limits.h"
#include "gl/State.h"
#include "src/base/Error.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {
constexpr std::size_t kVec4 = 4 * sizeof(float);
constexpr unsigned kFirstEpochs = 4;
}  // namespace

PerspectiveView::PerspectiveView(const SolverState& state, const gl::Buffer& nodes, std::size_t blockCount,
                                 unsigned decayShots, double interest, int resolution)
    : state_(state),
      nodes_(nodes),
      blocks_(blockCount),
      surfaces_(state.scene.polygons().size()),
      decayShots_(std::max(1u, decayShots)),
      byImportance_(interest > 0),
      resolution_(resolution),
      mesh_(state.scene, state.atlas),
      ids_(renderProgram("camera.vert", "view_id.frag")),
      seenPass_(computeProgram("view_surfaces.comp")),
      importantPass_(computeProgram("important_surfaces.comp")),
      pendingPass_(computeProgram("pending_blocks.comp")),
      deferredPass_(computeProgram("deferred_shooters.comp")),
      surfaceView_(surfaces_ * sizeof(glm::uvec4)),
      shotSoFar_(blocks_ * kVec4),
      seen_(surfaces_ * sizeof(std::uint32_t)),
      pending_(blocks_ * sizeof(float)),
      deferredBlocks_(blocks_ * sizeof(std::uint32_t)),
      visible_(surfaces_, 1),
      lastIn_(surfaces_, kNever),
      epoch_(surfaces_, -1),
      end_(surfaces_, -1) {
  shotSoFar_.clear(0.0f);
  pendingPass_.set("blockCount", unsigned(blocks_));
  double area = 0;
  for (const auto& pa : state.atlas.positionArea) area += pa.w;
  importantPass_.set("threshold", float(interest / area));
  uploadSurfaces();
}

// With the interest threshold, what the view needs beyond the camera's frustum is the important
// surfaces: the field of view stays the camera's, and the entries of the rest wait until the
// light runs out (showAll()); its steps only look again at what has become important.
double PerspectiveView::simulatedFov() const {
  if (byImportance_ && !wholeScene()) return camera_.fovY;
  return camera_.fovY + (180.0 - camera_.fovY) * double(std::min(step_, kSteps)) / kSteps;
}

std::size_t PerspectiveView::surfacesInView() const {
  return std::size_t(std::count(visible_.begin(), visible_.end(), 1));
}

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
  if (step_ >= lastStep()) return kNoStep;
  const unsigned at = lookShots_ + unsigned(std::uint64_t(decayShots_) * unsigned(step_ + 1) / kSteps);
  return at > shots ? at - shots : 0;
}

void PerspectiveView::grow(unsigned shots) {
  int step = step_;
  while (step < lastStep() && shots >= lookShots_ + unsigned(std::uint64_t(decayShots_) * unsigned(step + 1) / kSteps))
    ++step;
  if (step == step_) return;
  step_ = step;
  pending_view_ = true;
}

void PerspectiveView::showAll() {
  step_ = kSteps;
  pending_view_ = true;
}

bool PerspectiveView::update(unsigned shots) {
  if (!pending_view_ || !applyView(shots)) return false;
  pending_view_ = false;
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

  ids.bindImage(slot::IMAGE_VIEW_IDS, GL_READ_ONLY);
  seen_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SEEN);
  seenPass_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(w), 16), gl::groupsFor(unsigned(h), 16));
  gl::barrier(gl::Barrier::Storage);
  if (byImportance_) {
    state_.bindScene();
    state_.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_ONLY);
    importantPass_.use();
    gl::Program::dispatch(gl::groupsFor(unsigned(state_.atlas.width), 16),
                          gl::groupsFor(unsigned(state_.atlas.height), 16));
  }
  gl::barrier(gl::Barrier::BufferUpdate);
  std::vector<std::uint32_t> seen(surfaces_);
  seen_.read(0, seen.size() * sizeof(std::uint32_t), seen.data());
  return {seen.begin(), seen.end()};
}

int PerspectiveView::takeEpoch() {
  for (unsigned e = 0; e < capacity_; ++e)
    if (!slotUsed_[e]) return slotUsed_[e] = 1, int(e);
  // The snapshots are one storage block: on a large scene fewer epochs fit than kMaxEpochs.
  const std::size_t epochBytes = std::max<std::size_t>(blocks_, 1) * kVec4;
  const unsigned most = unsigned(std::min<std::size_t>(kMaxEpochs, gl::limits().storageBlockBytes / epochBytes));
  if (capacity_ >= most) return -1;
  const unsigned grown = std::min(most, std::max(kFirstEpochs, 2 * capacity_));
  gl::Buffer bigger(std::size_t(grown) * blocks_ * kVec4);
  if (capacity_) snapshots_.copyTo(bigger, 0, 0, std::size_t(capacity_) * blocks_ * kVec4);
  snapshots_ = std::move(bigger);
  slotUsed_.resize(grown, 0);
  const unsigned e = capacity_;
  capacity_ = grown;
  return slotUsed_[e] = 1, int(e);
}

bool PerspectiveView::applyView(unsigned shots) {
  std::vector<std::uint8_t> seen = wholeScene() ? std::vector<std::uint8_t>(surfaces_, 1) : renderSeen();
  // Hysteresis: what a view showed less than the decay interval ago stays (a walk's next frames
  // would mostly bring it back), and so does a surface still owed entries (they end at its epoch).
  // Before the first look() no view has shown anything.
  for (std::uint32_t p = 0; p < surfaces_; ++p)
    if (seen[p])
      lastIn_[p] = shots;
    else if (visible_[p] && (epoch_[p] >= 0 || (lastIn_[p] != kNever && shots - lastIn_[p] < decayShots_)))
      seen[p] = 1;
  std::vector<std::uint32_t> entering, leaving;
  for (std::uint32_t p = 0; p < surfaces_; ++p)
    if (visible_[p] != seen[p]) (seen[p] ? entering : leaving).push_back(p);
  if (entering.empty() && leaving.empty()) return true;
  const int e = takeEpoch();
  if (e < 0) return false;
  gl::barrier(gl::Barrier::BufferUpdate);  // shots so far, as select.comp left them
  shotSoFar_.copyTo(snapshots_, 0, std::size_t(e) * blocks_ * kVec4, blocks_ * kVec4);
  for (std::uint32_t p : leaving) visible_[p] = 0, epoch_[p] = e;
  for (std::uint32_t p : entering) visible_[p] = 1, end_[p] = e;  // owed from epoch_[p] to e
  if (round_.empty()) startRound();
  uploadSurfaces();
  return true;
}

// Seed 004 §5.5.2: the shooting locations of the entries owed to the round's surfaces.
void PerspectiveView::startRound() {
  while (round_.empty()) {
    std::vector<glm::uvec2> spans;
    for (std::uint32_t p = 0; p < surfaces_; ++p)
      if (visible_[p] && end_[p] >= 0) {
        round_.push_back(p);
        const glm::uvec2 span(epoch_[p], end_[p]);
        if (std::find(spans.begin(), spans.end(), span) == spans.end()) spans.push_back(span);
      }
    if (round_.empty()) return;
    if (spans_.size() < spans.size() * sizeof(glm::uvec2)) spans_ = gl::Buffer(surfaces_ * sizeof(glm::uvec2));
    spans_.upload(0, spans.size() * sizeof(glm::uvec2), spans.data());
    pendingPass_.set("spanCount", unsigned(spans.size()));
    bind();
    nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODES);
    pending_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PENDING);
    spans_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SPANS);
    pendingPass_.use();
    gl::dispatchLinear(gl::groupsFor(unsigned(blocks_), 256));
    gl::barrier(gl::Barrier::BufferUpdate);
    std::vector<float> power(blocks_);
    pending_.read(0, power.size() * sizeof(float), power.data());
    std::vector<std::uint32_t> list;
    for (std::uint32_t b = 0; b < blocks_; ++b)
      if (power[b] > 0) list.push_back(b);
    // The strongest entries first: the light the entering surfaces lack most arrives first.
    std::stable_sort(list.begin(), list.end(), [&](std::uint32_t a, std::uint32_t b) { return power[a] > power[b]; });
    if (!list.empty()) deferredBlocks_.upload(0, list.size() * sizeof(std::uint32_t), list.data());
    deferred_ = list.size();
    next_ = 0;
    if (!deferred_) endRound();  // nothing shot between: nothing owed (and the loop ends)
  }
}

void PerspectiveView::describeDeliveries(unsigned count, const gl::Buffer& control) {
  count = unsigned(std::min<std::size_t>(count, deliveriesLeft()));
  state_.bindScene();
  nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODES);
  control.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_CONTROL);
  deferredBlocks_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_DEFERRED_BLOCKS);
  deferredPass_.set("first", unsigned(next_));
  deferredPass_.set("count", count);
  deferredPass_.use();
  gl::Program::dispatch(gl::groupsFor(count, 64));
  gl::barrier(gl::Barrier::Storage | gl::Barrier::Command);
  next_ += count;
  deliveryTurn_ = false;
}

void PerspectiveView::finishDeliveries() {
  endRound();
  startRound();  // the surfaces that came into view meanwhile
  uploadSurfaces();
  gl::checkErrors("perspective view");
}

// The round's surfaces have all they were owed; the snapshot slots nobody refers to are free.
void PerspectiveView::endRound() {
  for (std::uint32_t p : round_) epoch_[p] = end_[p] = -1;
  round_.clear();
  deferred_ = next_ = 0;
  std::fill(slotUsed_.begin(), slotUsed_.end(), 0);
  for (std::size_t p = 0; p < surfaces_; ++p)
    for (int e : {epoch_[p], end_[p]})
      if (e >= 0) slotUsed_[std::size_t(e)] = 1;
}

// x: in view; y, z: 1 + the epochs where the entries the round hands a surface start and end.
void PerspectiveView::uploadSurfaces() {
  std::vector<glm::uvec4> v(surfaces_, glm::uvec4(0));
  for (std::size_t p = 0; p < surfaces_; ++p) v[p].x = visible_[p];
  for (std::uint32_t p : round_) v[p].y = std::uint32_t(epoch_[p] + 1), v[p].z = std::uint32_t(end_[p] + 1);
  surfaceView_.upload(0, v.size() * sizeof(glm::uvec4), v.data());
}

void PerspectiveView::bind() const {
  surfaceView_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SURFACE_VIEW);
  shotSoFar_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SHOT_SO_FAR);
  if (snapshots_)
    snapshots_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SNAPSHOTS);
  else
    shotSoFar_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SNAPSHOTS);  // no epoch yet: never read, but bound
}

}  // namespace hemirad

namespace hemirad {

namespace {

// Plain little-endian-as-in-memory fields, in a fixed order (checkpoints stay on one machine kind).
struct Writer {
  std::vector<std::uint8_t> bytes;
  template <class T>
  void put(const T& v) {
    putBytes(&v, sizeof v);
  }
  template <class T>
  void putVector(const std::vector<T>& v) {
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
  template <class T>
  T get() {
    T v;
    getBytes(&v, sizeof v);
    return v;
  }
  template <class T>
  std::vector<T> getVector(std::size_t most) {
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
  w.put(pending_view_), w.put(deliveryTurn_), w.put(std::uint64_t(deferred_)), w.put(std::uint64_t(next_));
  w.put(capacity_);
  w.putVector(visible_), w.putVector(lastIn_), w.putVector(epoch_), w.putVector(end_), w.putVector(slotUsed_);
  w.putVector(round_);
  std::vector<glm::vec4> table(blocks_ * (1 + std::size_t(capacity_)));  // shots so far, then the snapshots
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
  step_ = r.get<int>(), pending_view_ = r.get<bool>(), deliveryTurn_ = r.get<bool>();
  deferred_ = std::size_t(r.get<std::uint64_t>()), next_ = std::size_t(r.get<std::uint64_t>());
  capacity_ = r.get<unsigned>();
  visible_ = r.getVector<std::uint8_t>(surfaces_), lastIn_ = r.getVector<std::uint32_t>(surfaces_);
  epoch_ = r.getVector<int>(surfaces_), end_ = r.getVector<int>(surfaces_);
  slotUsed_ = r.getVector<std::uint8_t>(kMaxEpochs), round_ = r.getVector<std::uint32_t>(surfaces_);
  const std::vector<glm::vec4> table = r.getVector<glm::vec4>(blocks_ * (1 + kMaxEpochs));
  const std::vector<std::uint32_t> deferred = r.getVector<std::uint32_t>(blocks_);
  auto bad = [&](int e) { return e >= int(capacity_); };
  if (r.at != bytes.size() || visible_.size() != surfaces_ || lastIn_.size() != surfaces_ ||
      epoch_.size() != surfaces_ || end_.size() != surfaces_ || slotUsed_.size() != capacity_ ||
      table.size() != blocks_ * (1 + std::size_t(capacity_)) || deferred.size() != deferred_ || next_ > deferred_ ||
      std::any_of(epoch_.begin(), epoch_.end(), bad) || std::any_of(end_.begin(), end_.end(), bad) ||
      std::any_of(round_.begin(), round_.end(),
                  [&](std::uint32_t p) { return p >= surfaces_ || epoch_[p] < 0 || end_[p] < 0; }) ||
      std::any_of(deferred.begin(), deferred.end(), [&](std::uint32_t b) { return b >= blocks_; }))
    throw InputError("checkpoint: perspective view state is corrupt");
  shotSoFar_.upload(0, blocks_ * kVec4, table.data());
  snapshots_ = capacity_ ? gl::Buffer(std::size_t(capacity_) * blocks_ * kVec4) : gl::Buffer();
  if (capacity_) snapshots_.upload(0, std::size_t(capacity_) * blocks_ * kVec4, table.data() + blocks_);
  if (deferred_) deferredBlocks_.upload(0, deferred_ * sizeof(std::uint32_t), deferred.data());
  uploadSurfaces();
}

}  // namespace hemirad
