#pragma once
// Front door of the planning layer: graph search, visibility graphs on the map view, frontier targets,
// single- and multi-agent frontier choice, H-signatures.
#include "planning/graph.h"
#include "planning/navigation.h"
