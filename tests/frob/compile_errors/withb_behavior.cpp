// Must NOT compile: withB given a behavior where the paper gives a function of the task state. The
// message must show the fix, not a failed constraint spelling Point2 as an Eigen::Matrix.
#include <frob/frob.hpp>

using namespace frob;

Task<Wheels> circle() { co_return; }

Task<Wheels, Point2> closest(const Robot& r) {
  Point2 p = co_await withB(place(r), circle());
  co_return p;
}
