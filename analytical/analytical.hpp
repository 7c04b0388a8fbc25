#pragma once
// Everything in polydem::analytical, for callers that want it all (the CLI).
#include "analytical/beam_modes.hpp"
#include "analytical/collapse_diagram.hpp"
#include "analytical/constants.hpp"
#include "analytical/cracked_spire.hpp"
#include "analytical/free_rocking.hpp"
#include "analytical/ground_motion.hpp"
#include "analytical/rocking_body.hpp"
#include "analytical/rocking_cases.hpp"
#include "analytical/rocking_response.hpp"
#include "analytical/shell_sections.hpp"
#include "analytical/static_overturning.hpp"
