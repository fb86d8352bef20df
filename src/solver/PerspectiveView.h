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
// Without an interest threshold, the simulated field of view grows from the camera's to the
// whole scene in kSteps steps over `decayShots` shots after each camera move (seed 004's decay
// interval, counted in shots so a run is reproducible); once it covers the whole scene nothing
// is held back any more. With one, the field of view stays the camera's and the steps only
// look again at what has become important: the rest waits until showAll().
//
// A moving camera (issue 19): a surface leaves the area of interest only once no view has shown
// it for `decayShots` shots (hysteresis), so a walk does not hand the same surfaces their entries
// again every frame. A view applies at once, with a snapshot of its own: its entering surfaces
// receive shots from then on and are owed the entries up to it, which delivery rounds hand over
// in turn with shooting passes, strongest first; a round serves every surface owed entries when
// it starts, whatever view brought it in. A surface stays in view while it is owed entries.
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
  static constexpr int kSteps = 8;            // simulated field-of-view steps from the camera's to all
  static constexpr unsigned kMaxEpochs = 64;  // live snapshots; beyond, a new view waits for a round's end
  static constexpr unsigned kNoStep = std::numeric_limits<unsigned>::max();
  static constexpr std::uint32_t kNever = std::numeric_limits<std::uint32_t>::max();

  // `resolution`: pixels of the visibility view's longer side. `interest`: a surface with
  // received importance I - R above interest / (total area) somewhere (1: the view's importance
  // spread evenly) is in the area of interest wherever it is; 0: only the simulated field of view.
  // `nodes`: the shooter tree (ShooterTree.h), whose first `blockCount` nodes are the blocks.
  PerspectiveView(const SolverState& state, const gl::Buffer& nodes, std::size_t blockCount, unsigned decayShots,
                  double interest = 0, int resolution = 256);

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
  // stored entries of the surfaces it brings in are then delivered a few item buffers at a time,
  // a delivery pass in turn with a shooting pass (so a frame's budget holds and shooting goes on;
  // the entries stay exact).
  bool settled() const { return !pending_view_ && round_.empty(); }
  bool delivering() const { return !round_.empty(); }
  bool deliveryTurn() const { return delivering() && deliveryTurn_; }  // the next pass delivers
  void shot() { deliveryTurn_ = true; }                                // after a shooting pass
  bool update(unsigned shots);  // applies a waiting view at `shots`; true if it did
  // Blocks whose entries are still to deliver; describes the next `count` of them as the pass's
  // shooters (gather.comp, delivery mode).
  std::size_t deliveriesLeft() const { return deferred_ - next_; }
  void describeDeliveries(unsigned count, const gl::Buffer& control);
  void finishDeliveries();  // after the pass of the last of a round's

  // Binds the surface view (6), shots so far (7) and snapshots (8) for select.comp and gather.comp.
  void bind() const;

  // Checkpoints: the whole state (view, epochs, table, deliveries under way), so a resumed
  // solve goes on bitwise. restore() throws InputError for bytes of another scene.
  std::vector<std::uint8_t> save() const;
  void restore(std::span<const std::uint8_t> bytes);

 private:
  bool applyView(unsigned shots);                                       // false: no snapshot slot free, the view waits
  int lastStep() const { return byImportance_ ? kSteps - 1 : kSteps; }  // growth ends there
  std::vector<std::uint8_t> renderSeen();
  int takeEpoch();    // a free snapshot slot, -1 if none
  void startRound();  // the surfaces owed entries now, and the blocks with entries for them
  void endRound();
  void uploadSurfaces();

  const SolverState& state_;
  const gl::Buffer& nodes_;
  std::size_t blocks_, surfaces_;
  unsigned decayShots_;
  bool byImportance_;
  int resolution_;
  CameraMesh mesh_;
  gl::Program ids_, seenPass_, importantPass_, pendingPass_, deferredPass_;
  gl::Buffer surfaceView_, shotSoFar_, snapshots_, seen_, pending_, deferredBlocks_, spans_;
  unsigned capacity_ = 0;  // snapshot slots allocated

  Camera camera_;
  double aspect_ = 1;
  unsigned lookShots_ = 0;
  bool looked_ = false;
  int step_ = kSteps;  // until the first look() everything is in view
  std::vector<std::uint8_t> visible_;
  std::vector<std::uint32_t> lastIn_;    // per surface: shots when a view last showed it (kNever: none)
  std::vector<int> epoch_;               // per surface: the epoch its entries started, -1 none
  std::vector<int> end_;                 // ... and, back in view, the epoch they end at, -1 none
  std::vector<std::uint8_t> slotUsed_;   // per snapshot slot
  std::vector<std::uint32_t> round_;     // the surfaces the delivery round under way serves
  std::size_t deferred_ = 0, next_ = 0;  // its blocks with entries, delivered so far
  bool pending_view_ = false, deliveryTurn_ = true;
};

}  // namespace hemirad
