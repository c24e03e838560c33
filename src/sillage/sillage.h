#pragma once
// sillage: guaranteed state estimation by constraint programming over
// intervals and tubes. This header brings in the whole public API.

#include "sillage/error.h"

#include "sillage/interval/backward.h"
#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"
#include "sillage/interval/interval_matrix.h"
#include "sillage/interval/interval_vector.h"

#include "sillage/expr/expr.h"
#include "sillage/expr/function.h"

#include "sillage/ctc/ctc.h"
#include "sillage/ctc/ctc_algebra.h"
#include "sillage/ctc/ctc_binary.h"
#include "sillage/ctc/ctc_box.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/ctc_qinter.h"
#include "sillage/ctc/ctc_unary.h"
#include "sillage/ctc/gomne.h"
#include "sillage/ctc/sep.h"
#include "sillage/ctc/sep_algebra.h"
#include "sillage/ctc/sep_ctc_pair.h"
#include "sillage/ctc/sep_function.h"

#include "sillage/cn/contractor_network.h"
#include "sillage/cn/network_ctc.h"
#include "sillage/cn/tube_ctc_node.h"
#include "sillage/cn/tube_domain.h"

#include "sillage/paving/component.h"
#include "sillage/paving/contour.h"
#include "sillage/paving/paving.h"
#include "sillage/paving/sivia.h"
#include "sillage/paving/sivia_function.h"

#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tdomain.h"
#include "sillage/tube/trajectory.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_arithmetic.h"
#include "sillage/tube/tube_builders.h"
#include "sillage/tube/tube_ctc.h"
#include "sillage/tube/tube_integral.h"
#include "sillage/tube/tube_taylor.h"
#include "sillage/tube/tube_io.h"
#include "sillage/tube/tube_vector.h"

#include "sillage/dynamics/ctc_deriv.h"
#include "sillage/dynamics/ctc_eval.h"
#include "sillage/dynamics/ctc_increment.h"
#include "sillage/dynamics/tube_nodes.h"
#include "sillage/io/csv.h"
#include "sillage/dynamics/time_propag.h"

#include "sillage/loops/loop_function.h"
#include "sillage/loops/path_crossings.h"
#include "sillage/loops/plane_function.h"
#include "sillage/loops/topological_degree.h"
#include "sillage/loops/tplane.h"
#include "sillage/loops/zero_tests.h"

#include "sillage/figures/figure.h"
#include "sillage/figures/html.h"
#include "sillage/figures/thickness_figure.h"
#include "sillage/figures/tube_figure.h"
