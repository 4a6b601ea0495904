// Drives carefully only when it is filmed: its picture notes in a global when it is drawn, and the
// wheels read that note. In a run where pictures are sampled only for a video, the graded run would
// drive fast and the film slow.
#include "misbehave.hpp"
bool filmed = false;
Task<Wheels> carefulWhenFilmed() {
  const Behavior<Picture> marker = lift(
      [](double) {
        filmed = true;
        return Picture();
      },
      time());
  co_await withPicture(marker, mkTask([](const TaskState&) {
                         return std::pair{toBehavior(lift([](double) { return Wheels{filmed ? 0.1 : 0.3, 0.0}; }, time())), never<Unit>()};
                       }));
}
FROB_CONTROLLER(carefulWhenFilmed)
