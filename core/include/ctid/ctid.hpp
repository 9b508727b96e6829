// SPDX-License-Identifier: BSD-3-Clause
// Copyright (C) the ctid authors
// ctid: every layer of the numerical core in one include, for users of the
// installed C++ API who do not want to pick headers (see the README, "Layout").
// The NLopt-based minimiser (adaptation/nlopt_minimizer.hpp) is left out so
// that this header needs only Eigen; include it where NLopt is linked.
#pragma once

#include "ctid/adaptation/adaptation.hpp"
#include "ctid/adaptation/covariance_guard.hpp"
#include "ctid/adaptation/lmr.hpp"
#include "ctid/adaptation/potter.hpp"
#include "ctid/adaptation/qn_ml.hpp"
#include "ctid/apps/residtrace/responses.hpp"
#include "ctid/apps/residtrace/statistics.hpp"
#include "ctid/apps/residtrace/track.hpp"
#include "ctid/apps/throttle.hpp"
#include "ctid/base/delay_line.hpp"
#include "ctid/base/model.hpp"
#include "ctid/base/record.hpp"
#include "ctid/base/stability.hpp"
#include "ctid/base/status.hpp"
#include "ctid/base/types.hpp"
#include "ctid/filters/auxiliary_model.hpp"
#include "ctid/filters/discretization.hpp"
#include "ctid/filters/svf.hpp"
#include "ctid/filters/svf_regressor.hpp"
#include "ctid/offline/freq_srivc.hpp"
#include "ctid/offline/hammerstein.hpp"
#include "ctid/offline/least_squares.hpp"
#include "ctid/offline/offline_iv.hpp"
#include "ctid/offline/output_error.hpp"
#include "ctid/offline/refined_iv.hpp"
#include "ctid/offline/refined_iv_bj.hpp"
#include "ctid/recursive/recursive_arx.hpp"
#include "ctid/recursive/recursive_iv.hpp"
#include "ctid/recursive/rlssvf.hpp"
#include "ctid/recursive/scaling.hpp"
#include "ctid/simulation/controller.hpp"
#include "ctid/simulation/effect_simulator.hpp"
#include "ctid/simulation/ltv_simulator.hpp"
#include "ctid/simulation/physical_realisations.hpp"
