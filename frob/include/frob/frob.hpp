#pragma once
/// Frob: functional reactive robotics. The one header a controller includes.

#include "frob/behavior.hpp"
#include "frob/calculus.hpp"
#include "frob/errors.hpp"
#include "frob/event.hpp"
#include "frob/geometry.hpp"
#include "frob/instant.hpp"
#include "frob/picture.hpp"
#include "frob/robot.hpp"
#include "frob/robot_values.hpp"
#include "frob/sampling.hpp"
#include "frob/switching.hpp"
#include "frob/task.hpp"
#include "frob/task_transformers.hpp"
#include "frob/parallel.hpp"
