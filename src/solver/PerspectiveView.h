// Perspective-driven shooting (seed 004 §5): the area of interest (the surfaces a view with a
// simulated field of view sees) and the stored radiosity table for the surfaces outside it.
//
// Only surfaces in view receive radiosity (gather.comp, viewMode 1). What a shot would have
// given the others is their table entry: the table is kept factored (shaders/perspective.glsl)
// as the radiosity each shooter block has shot so far and snapshots of that vector, one per
// epoch, taken when surfaces leave the view. A surface entering the view receives from every
// block that shot since its epoch began (seed 004 §5.5: the becoming-visible vector, the
// shooting-locations vector, one item buffer per block for all entering surfaces: bucketing).
// Memory is O(blocks x live epochs), for any number of surfaces.
//
// The simulated field of view grows from the camera's to the whole scene in kSteps steps over
// `decayShots` shots after each camera move (seed 004's decay interval, counted in shots so a
// run is reproducible); once it covers the whole scene nothing is held back any more.
#pragma once
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "gl/Objects.h"
#include "src/scene/Camera.h"
#include "src/solver/CameraMesh.h"
#include "src/solver/SolverState.h"

namespace hemirad {

class PerspectiveView {
 public:
  static constexpr int kSteps = 8;          // simulated field-of-view steps from the camera's to all
  static constexpr unsigned kMaxEpochs = 64;  // live snapshots; the oldest is delivered beyond that
  static constexpr unsigned kNoStep = std::numeric_limits<unsigned>::max();


  // `resolution`: pixels of the visibility view's longer side. `interest`: a surface with
  // received importance I - R above interest / (total area) somewhere (1: the view's importance
  // spread evenly) is in the area of interest wherever it is; 0: only the simulated field of view.
  PerspectiveView(const SolverState& state, std::size_t blockCount, unsigned decayShots, double interest = 0,
                  int resolution = 256);

  // A camera move at `shots` shots: the simulated field of view restarts at the camera's.
  // The view it already has is no move (a resumed solve looks again): nothing changes.
  void look(const Camera& camera, double aspect, unsigned shots);
  // Shots left until the simulated field of view next grows; kNoStep once it holds everything.
  unsigned shotsToNextStep(unsigned shots) const;
  // Grows the simulated field of view to where it stands after `shots` shots.
  void grow(unsigned shots);
  void showAll();  // the whole scene is the area of interest from now until the next look()
  bool wholeScene() const { return step_ >= kSteps; }
  double simulatedFov() const;
  unsigned decayShots() const { return decayShots_; }
  std::size_t surfacesInView() const;

  // look(), grow() and showAll() only record the new view; it takes effect in update(), and the
  // stored entries of the surfaces it brings in are then delivered a few item buffers at a time
  // (so a frame's budget holds). While they are, nothing is shot (the entries stay exact), and a
  // newer view waits: the latest one applies once the deliveries are done.
  bool settled() const { return !pending_view_ && !delivering_; }
  bool delivering() const { return delivering_; }
  bool update();  // applies a waiting view (not while delivering); true if it did
  // Blocks whose entries are still to deliver; describes the next `count` of them as the pass's
  // shooters (gather.comp, delivery mode).
  std::size_t deliveriesLeft() const { return deferred_ - next_; }
  void describeDeliveries(unsigned count, const gl::Buffer& nodes, const gl::Buffer& control);
  void finishDeliveries();  // after the pass of the last of them

  // Binds the surface view (6), shots so far (7) and snapshots (8) for select.comp and gather.comp.
  void bind() const;

  // Checkpoints: the whole state (view, epochs, table, deliveries under way), so a resumed
  // solve goes on bitwise. restore() throws InputError for bytes of another scene.
  std::vector<std::uint8_t> save() const;
  void restore(std::span<const std::uint8_t> bytes);

 private:
  void applyView();
  std::vector<std::uint8_t> renderSeen();
  unsigned takeEpoch(const std::vector<std::uint8_t>& seen);
  void uploadSurfaces(bool delivering);

  const SolverState& state_;
  std::size_t blocks_, surfaces_;
  unsigned decayShots_;
  bool byImportance_;
  int resolution_;
  CameraMesh mesh_;
  gl::Program ids_, seenPass_, importantPass_, pendingPass_, deferredPass_;
  gl::Buffer surfaceView_, shotSoFar_, snapshots_, seen_, pending_, deferredBlocks_;
  unsigned capacity_ = 0;  // snapshot slots allocated

  Camera camera_;
  double aspect_ = 1;
  unsigned lookShots_ = 0;
  bool looked_ = false;
  int step_ = kSteps;  // until the first look() everything is in view
  std::vector<std::uint8_t> visible_;
  std::vector<int> epoch_;                // per surface: the epoch its entries started, -1 none
  std::vector<std::uint64_t> epochBirth_;  // per slot: when it was taken (0: free)
  std::uint64_t births_ = 0;
  std::vector<std::uint32_t> entering_;   // surfaces receiving their entries now
  std::vector<std::uint8_t> staysOut_;    // ... of which these stay out of view (oldest epoch flushed)
  int newEpoch_ = -1;                     // the slot taken for this change, snapshot at finish
  std::size_t deferred_ = 0, next_ = 0;
  bool pending_view_ = false, delivering_ = false;
};

}  // namespace hemirad
