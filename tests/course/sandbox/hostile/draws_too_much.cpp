// Well-meaning, but draws five polylines of 4096 points each (within the caps of shapes and points,
// past what a step's reply holds) from half a second on, driving ahead meanwhile.
#include "misbehave.hpp"

#include <vector>

Task<Wheels> drawsTooMuch() {
  Picture huge;
  for (int s = 0; s < 5; ++s) {
    std::vector<Point2> points;
    for (int i = 0; i < 4096; ++i) points.push_back(Point2{1 + s * 0.5, 1 + i * 5e-4});
    huge = huge + polyline(std::move(points));
  }
  co_await mkTask([](const TaskState&) { return std::pair{wheels(0.1, 0.0), after(0.5)}; });
  co_await withPicture(constant(huge), mkTask([](const TaskState&) { return std::pair{wheels(0.1, 0.0), never<Unit>()}; }));
}
FROB_CONTROLLER(drawsTooMuch)
