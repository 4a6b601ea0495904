#pragma once
/// Frob: functional reactive robotics. The one header a controller includes.
/// Where to start: frob/README.md lists every public name, grouped, with its meaning and header;
/// course/examples/01_run_around.cpp is the first program, course/lessons/ the course. Each header
/// below is a list of `///`-commented declarations, task.hpp and behavior.hpp first; the machinery
/// behind them is in frob/detail/, which a controller never needs to read.

#include "frob/behavior.hpp"
#include "frob/calculus.hpp"
#include "frob/controller.hpp"
#include "frob/debug.hpp"
#include "frob/errors.hpp"
#include "frob/event.hpp"
#include "frob/geometry.hpp"
#include "frob/instant.hpp"
#include "frob/parallel.hpp"
#include "frob/picture.hpp"
#include "frob/robot.hpp"
#include "frob/robot_values.hpp"
#include "frob/run_task.hpp"
#include "frob/sampling.hpp"
#include "frob/sensing.hpp"
#include "frob/switching.hpp"
#include "frob/task.hpp"
#include "frob/task_state.hpp"
#include "frob/task_transformers.hpp"
