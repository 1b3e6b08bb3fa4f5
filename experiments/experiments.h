#pragma once
// Front door of the experiments layer: configuration, pictures and world checks used by the CLI.
#include "experiments/config.h"
#include "experiments/draw.h"
#include "experiments/map_drive.h"
#include "experiments/navigation_trial.h"
#include "experiments/recorded.h"
#include "experiments/sensor_factory.h"
#include "experiments/trial.h"
#include "experiments/world_checks.h"
