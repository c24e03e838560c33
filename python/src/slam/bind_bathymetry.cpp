// Python bindings of the synthetic bathymetric mission (missions/bathymetry_*.h):
// seabed DEM, mission, sensors and bounds, tide model, tube builders, figures.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.h"
#include "docstrings.h"
#include "sillage/missions/bathymetry_dem.h"
#include "sillage/missions/bathymetry_figures.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_range_observation.h"
#include "sillage/missions/bathymetry_seabed.h"
#include "sillage/missions/bathymetry_sensors.h"
#include "sillage/slam/bathymetry_tide.h"
#include "sillage/missions/bathymetry_tubes.h"

namespace sillage::python {

namespace {

py::array_t<double> array_of(const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); }

using Mission = BathymetryMission;
using MissionPtr = std::shared_ptr<Mission>;

void init_bathymetry_data(py::module_& m) {
  py::class_<ChannelBank>(m, "ChannelBank", DOC(ChannelBank))
      .def(py::init([](double height, double width, double direction, double x, double y) {
             return ChannelBank{height, width, direction, x, y};
           }),
           py::arg("height") = ChannelBank{}.height, py::arg("width") = ChannelBank{}.width,
           py::arg("direction") = ChannelBank{}.direction, py::arg("x") = ChannelBank{}.x,
           py::arg("y") = ChannelBank{}.y, "Every field by keyword (defaults: 15 m over 30 m, downslope east, "
           "through (250, 250)).")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .SILLAGE_FIELDS(ChannelBank, height, width, direction, x, y);
  py::class_<SeabedOptions>(m, "SeabedOptions", DOC(SeabedOptions))
      .def(py::init<>(), "Defaults: 500 m square, 1 m cells, 21 m base depth, 170 m smooth strip, 7 rocks, 2 banks.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .SILLAGE_FIELDS(SeabedOptions, size, cell, base_depth, smooth_width, nb_rocks, nb_banks, relief, rock_height_min,
                      rock_height_max, rock_sigma_min, rock_sigma_max, dune_height)
      .def_readwrite("channel_banks", &SeabedOptions::channel_banks,
                     DOC(SeabedOptions, channel_banks) "\nPython: a copy (a list); assign a new list to change it.");
  m.SILLAGE_FN(coastal_seabed_options);
  m.SILLAGE_FN(bank_seabed_options);
  py::class_<SeabedClass>(m, "SeabedClass",
                          DOC(SeabedClass))
      .def(py::init<double, double, double>(), py::arg("curvature"), py::arg("slope"), py::arg("roughness"),
           "The three bounds.")
      .def("__repr__", [](const SeabedClass& c) { return repr(c); }, "SeabedClass(curvature, slope, roughness).")
      .SILLAGE_FIELDS(SeabedClass, curvature, slope, roughness);

  py::class_<BathymetryDem, std::shared_ptr<BathymetryDem>>(
      m, "BathymetryDem",
      DOC(BathymetryDem))
      .def(py::init([](double x0, double y0, double h, const py::array_t<double, py::array::c_style |
                                                                              py::array::forcecast>& depths) {
             if (depths.ndim() != 2) throw DimensionError("BathymetryDem: depths must be a 2-D array (ny, nx)");
             const auto ny = static_cast<std::size_t>(depths.shape(0)), nx = static_cast<std::size_t>(depths.shape(1));
             return BathymetryDem(x0, y0, h, nx, ny, std::vector<double>(depths.data(), depths.data() + nx * ny));
           }),
           py::arg("x0"), py::arg("y0"), py::arg("h"), py::arg("depths"),
           "Nodes (x0 + i h, y0 + j h) with depth depths[j, i] (metres, positive down).")
      .def("__repr__", [](const BathymetryDem& d) { return repr(d); }, "A one-line summary.")
      .SILLAGE_PROPERTIES(BathymetryDem, nx, ny, cell_size, x0, y0)
      .SILLAGE_DEF(BathymetryDem, domain)
      .SILLAGE_DEF(BathymetryDem, node, py::arg("i"), py::arg("j"))
      .def(
          "depths",
          [](const BathymetryDem& d) {
            py::array_t<double> a({d.ny(), d.nx()});
            std::copy(d.depths().begin(), d.depths().end(), a.mutable_data());
            return a;
          },
          DOC(BathymetryDem, depths))
      .SILLAGE_DEFS(BathymetryDem, min_depth, max_depth)
      .def("__call__", &BathymetryDem::operator(), py::arg("x"), py::arg("y"),
           DOC(BathymetryDem, op_call))
      .SILLAGE_DEF(BathymetryDem, eval, py::arg("box"))
      .SILLAGE_DEF(BathymetryDem, eval_cells, py::arg("box"));

  py::class_<Seabed>(m, "Seabed", DOC(Seabed))
      .def("__repr__", [](const Seabed& s) { return "Seabed(" + repr(s.dem) + ", " + repr(s.bounds) + ")"; },
           "A one-line summary.")
      .SILLAGE_READONLY_FIELDS(Seabed, dem, bounds, smooth_region);
  m.SILLAGE_FN(generate_seabed, py::arg("seed"), py::arg("options") = SeabedOptions{}, nogil);

  py::class_<TideModel>(m, "TideModel", DOC(TideModel))
      .def(py::init([](double range, double duration, double t_low, const Interval& error) {
             return TideModel{range, duration, t_low, error};
           }),
           py::arg("range") = 5.2, py::arg("duration") = 22320.0, py::arg("t_low") = -5400.0,
           py::arg("error") = Interval(0.0),
           "Defaults: range 5.2 m, duration 22320 s, low water 5400 s before the start, no model error.")
      .def("__repr__", [](const TideModel& t) { return repr(t); }, "TideModel(range, duration, t_low).")
      .SILLAGE_FIELDS(TideModel, range, duration, t_low, error)
      .def("__call__", &TideModel::operator(), py::arg("t"), DOC(TideModel, op_call))
      .SILLAGE_DEF(TideModel, height, py::arg("t"))
      .SILLAGE_DEF(TideModel, height_value, py::arg("t"));

  py::class_<BathymetrySensorBounds>(m, "BathymetrySensorBounds",
                                     DOC(BathymetrySensorBounds))
      .def(py::init<>(), "Defaults: DVL +-(0.2 % + 1 mm/s), INS +-0.05 deg, depth +-0.05 m, altitude +-(1 % + 5 cm), "
                         "tide +-0.1 m.")
      .def("__repr__", [](const BathymetrySensorBounds& b) { return repr(b); }, "A one-line summary.")
      .SILLAGE_FIELDS(BathymetrySensorBounds, dvl_scale, dvl_offset, heading, attitude, depth, altitude_scale,
                      altitude_offset, tide, angle_accel, velocity_accel2, speed_max, beam_angle, beam_spread,
                      beam_azimuth_spread);
  m.SILLAGE_FN(dvl_footprint, py::arg("x"), py::arg("y"), py::arg("yaw"), py::arg("altitude"),
               py::arg("bounds") = BathymetrySensorBounds{});
  m.SILLAGE_FN(footprint_depth, py::arg("dem"), py::arg("x"), py::arg("y"), py::arg("yaw"), py::arg("altitude"),
               py::arg("bounds") = BathymetrySensorBounds{});
  m.SILLAGE_FN(footprint_filter_bound, py::arg("seabed"), py::arg("cell"), py::arg("altitude_max"),
               py::arg("bounds") = BathymetrySensorBounds{});
  m.SILLAGE_FN(nadir_altitude_max, py::arg("measured"), py::arg("seabed"), py::arg("cell"),
               py::arg("bounds") = BathymetrySensorBounds{});
}

void init_bathymetry_mission(py::module_& m) {
  py::class_<BathymetryMissionOptions>(m, "BathymetryMissionOptions", DOC(BathymetryMissionOptions))
      .def(py::init<>(), "Defaults: 5760 s at 0.1 s, 1.03 m/s, 28 m turns, 40 m rails, 14.5 m depth.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .SILLAGE_FIELDS(BathymetryMissionOptions, duration, step, speed, turn_radius, rail_spacing, depth, transects,
                      tie_line_angle, seabed, tide, bounds);
  m.SILLAGE_FN(bank_mission_options);

  py::class_<BathymetrySignals>(m, "BathymetrySignals",
                                "Signals at the sample times (numpy arrays): yaw, pitch, roll (rad), vx, vy, vz "
                                "(body, m/s), depth, altitude (m).")
      .def("__repr__", [](const BathymetrySignals& s) { return "BathymetrySignals(" + std::to_string(s.yaw.size()) +
                                                               " samples)"; },
           "BathymetrySignals(n samples).")
#define SILLAGE_SIGNAL(name, doc) \
  .def_property_readonly(#name, [](const BathymetrySignals& s) { return array_of(s.name); }, doc)
      SILLAGE_SIGNAL(yaw, "Yaw, counter-clockwise from east (rad).")
      SILLAGE_SIGNAL(pitch, "Pitch, positive nose down (rad).")
      SILLAGE_SIGNAL(roll, "Roll (rad).")
      SILLAGE_SIGNAL(vx, "Body velocity, forward (m/s).")
      SILLAGE_SIGNAL(vy, "Body velocity, left (m/s).")
      SILLAGE_SIGNAL(vz, "Body velocity, up (m/s).")
      SILLAGE_SIGNAL(depth, "Depth below the surface (m).")
      SILLAGE_SIGNAL(altitude, "Altitude (m): nadir (truth) or DVL (measured).");
#undef SILLAGE_SIGNAL

  py::class_<Mission, MissionPtr>(m, "BathymetryMission",
                                  DOC(BathymetryMission))
      .def(py::init([](std::uint64_t seed, const std::optional<BathymetryMissionOptions>& o) {
             py::gil_scoped_release unlocked;
             return std::make_shared<Mission>(seed, o ? *o : BathymetryMissionOptions{});
           }),
           py::arg("seed") = 7, py::arg("options") = py::none(), DOC(BathymetryMission, BathymetryMission))
      .def("__repr__", [](const Mission& x) { return repr(x); }, "A one-line summary.")
      .SILLAGE_PROPERTIES(BathymetryMission, seed, options, seabed, dem, bounds, tide, nb_samples)
      .def_property_readonly("times", [](const Mission& x) { return array_of(x.times()); }, DOC(BathymetryMission, times))
      .def_property_readonly("x1", [](const Mission& x) { return array_of(x.x1()); }, DOC(BathymetryMission, x1))
      .def_property_readonly("x2", [](const Mission& x) { return array_of(x.x2()); }, DOC(BathymetryMission, x2))
      .SILLAGE_PROPERTIES(BathymetryMission, truth, measured)
      .def_property_readonly("tide_truth", [](const Mission& x) { return array_of(x.tide_truth()); },
                             DOC(BathymetryMission, tide_truth))
      .def_property_readonly("filtered_altitude", [](const Mission& x) { return array_of(x.filtered_altitude()); },
                             DOC(BathymetryMission, filtered_altitude))
      .SILLAGE_DEF(BathymetryMission, path_length)
      .SILLAGE_DEF(BathymetryMission, tdomain, py::arg("dt"))
      .SILLAGE_DEF(BathymetryMission, sample_index, py::arg("t"));

  m.SILLAGE_FN(bathymetry_sensor_tubes, py::arg("mission"), py::arg("tdomain"), nogil);
  m.SILLAGE_FN(bathymetry_velocity_tube, py::arg("mission"), py::arg("tdomain"), nogil);
  m.SILLAGE_FN(bathymetry_dead_reckoning, py::arg("mission"), py::arg("tdomain"), py::arg("x0"), nogil);
  m.SILLAGE_FN(bathymetry_initial_box, py::arg("mission"), py::arg("horizontal") = 1.0);
  m.SILLAGE_FN(bathymetry_observation_tube, py::arg("mission"), py::arg("tdomain"), nogil);
  m.SILLAGE_FN(bathymetry_observation_rate_bound, py::arg("mission"));
  m.SILLAGE_FN(bathymetry_truth, py::arg("mission"));
  m.SILLAGE_FN(bathymetry_truth_observation, py::arg("mission"));

  m.SILLAGE_FN(depth_colour, py::arg("depth"), py::arg("lo"), py::arg("hi"));
  m.SILLAGE_FN(bathymetry_dem_figure, py::arg("dem"), py::arg("x"), py::arg("y"),
               py::arg("title") = "Seabed DEM and path", py::arg("block") = 5.0, py::arg("width_px") = 600.0);
  m.SILLAGE_FN(bathymetry_map_figure, py::arg("mission"), py::arg("p"),
               py::arg("title") = "Mission map: dead reckoning and truth", py::arg("width_px") = 600.0);
  m.SILLAGE_FN(bathymetry_observation_figure, py::arg("mission"), py::arg("z"),
               py::arg("title") = "Observation tube [z](t) and truth", py::arg("width_px") = 700.0);
}

void init_range_observation(py::module_& m) {
  py::class_<RangeBounds>(m, "RangeBounds",
                          DOC(RangeBounds))
      .def(py::init<>(), "Defaults (plaza1): short 1.5 m, long 10 m, time stamps 0.2 s, speed 2 m/s.")
      .def(py::init<double, double, double, double>(), py::arg("short_err"), py::arg("long_err"),
           py::arg("time_err"), py::arg("speed"), "The four bounds.")
      .def("__repr__", [](const RangeBounds& b) { return repr(b); }, "RangeBounds(short_err, long_err, ...).")
      .SILLAGE_FIELDS(RangeBounds, short_err, long_err, time_err, speed);
  m.SILLAGE_FN(range_observation_tubes, py::arg("tdomain"), py::arg("times"), py::arg("beacon"), py::arg("range"),
               py::arg("beacon_ids"), py::arg("bounds") = RangeBounds{}, nogil);
}

}  // namespace

SILLAGE_BINDING(bathymetry, "figures", "interval", "tdomain", "trajectory", "tube") {
  init_bathymetry_data(m);
  init_bathymetry_mission(m);
  init_range_observation(m);
}

}  // namespace sillage::python
