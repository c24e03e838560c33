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
      .def_readwrite("height", &ChannelBank::height, DOC(ChannelBank, height))
      .def_readwrite("width", &ChannelBank::width, DOC(ChannelBank, width))
      .def_readwrite("direction", &ChannelBank::direction, DOC(ChannelBank, direction))
      .def_readwrite("x", &ChannelBank::x, DOC(ChannelBank, x))
      .def_readwrite("y", &ChannelBank::y, DOC(ChannelBank, y));
  py::class_<SeabedOptions>(m, "SeabedOptions", DOC(SeabedOptions))
      .def(py::init<>(), "Defaults: 500 m square, 1 m cells, 21 m base depth, 170 m smooth strip, 7 rocks, 2 banks.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def_readwrite("size", &SeabedOptions::size, DOC(SeabedOptions, size))
      .def_readwrite("cell", &SeabedOptions::cell, DOC(SeabedOptions, cell))
      .def_readwrite("base_depth", &SeabedOptions::base_depth, DOC(SeabedOptions, base_depth))
      .def_readwrite("smooth_width", &SeabedOptions::smooth_width, DOC(SeabedOptions, smooth_width))
      .def_readwrite("nb_rocks", &SeabedOptions::nb_rocks, DOC(SeabedOptions, nb_rocks))
      .def_readwrite("nb_banks", &SeabedOptions::nb_banks, DOC(SeabedOptions, nb_banks))
      .def_readwrite("relief", &SeabedOptions::relief, DOC(SeabedOptions, relief))
      .def_readwrite("rock_height_min", &SeabedOptions::rock_height_min, DOC(SeabedOptions, rock_height_min))
      .def_readwrite("rock_height_max", &SeabedOptions::rock_height_max, DOC(SeabedOptions, rock_height_max))
      .def_readwrite("rock_sigma_min", &SeabedOptions::rock_sigma_min, DOC(SeabedOptions, rock_sigma_min))
      .def_readwrite("rock_sigma_max", &SeabedOptions::rock_sigma_max, DOC(SeabedOptions, rock_sigma_max))
      .def_readwrite("dune_height", &SeabedOptions::dune_height, DOC(SeabedOptions, dune_height))
      .def_readwrite("channel_banks", &SeabedOptions::channel_banks,
                     DOC(SeabedOptions, channel_banks) "\nPython: a copy (a list); assign a new list to change it.");
  m.def("coastal_seabed_options", &coastal_seabed_options, DOC(coastal_seabed_options));
  m.def("bank_seabed_options", &bank_seabed_options, DOC(bank_seabed_options));
  py::class_<SeabedClass>(m, "SeabedClass",
                          DOC(SeabedClass))
      .def(py::init<double, double, double>(), py::arg("curvature"), py::arg("slope"), py::arg("roughness"),
           "The three bounds.")
      .def("__repr__", [](const SeabedClass& c) { return repr(c); }, "SeabedClass(curvature, slope, roughness).")
      .def_readwrite("curvature", &SeabedClass::curvature, DOC(SeabedClass, curvature))
      .def_readwrite("slope", &SeabedClass::slope, DOC(SeabedClass, slope))
      .def_readwrite("roughness", &SeabedClass::roughness, DOC(SeabedClass, roughness));

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
      .def_property_readonly("nx", &BathymetryDem::nx, DOC(BathymetryDem, nx))
      .def_property_readonly("ny", &BathymetryDem::ny, DOC(BathymetryDem, ny))
      .def_property_readonly("cell_size", &BathymetryDem::cell_size, DOC(BathymetryDem, cell_size))
      .def_property_readonly("x0", &BathymetryDem::x0, DOC(BathymetryDem, x0))
      .def_property_readonly("y0", &BathymetryDem::y0, DOC(BathymetryDem, y0))
      .def("domain", &BathymetryDem::domain, DOC(BathymetryDem, domain))
      .def("node", &BathymetryDem::node, py::arg("i"), py::arg("j"), DOC(BathymetryDem, node))
      .def(
          "depths",
          [](const BathymetryDem& d) {
            py::array_t<double> a({d.ny(), d.nx()});
            std::copy(d.depths().begin(), d.depths().end(), a.mutable_data());
            return a;
          },
          DOC(BathymetryDem, depths))
      .def("min_depth", &BathymetryDem::min_depth, DOC(BathymetryDem, min_depth))
      .def("max_depth", &BathymetryDem::max_depth, DOC(BathymetryDem, max_depth))
      .def("__call__", &BathymetryDem::operator(), py::arg("x"), py::arg("y"),
           DOC(BathymetryDem, op_call))
      .def("eval", &BathymetryDem::eval, py::arg("box"),
           DOC(BathymetryDem, eval))
      .def("eval_cells", &BathymetryDem::eval_cells, py::arg("box"),
           DOC(BathymetryDem, eval_cells));

  py::class_<Seabed>(m, "Seabed", DOC(Seabed))
      .def("__repr__", [](const Seabed& s) { return "Seabed(" + repr(s.dem) + ", " + repr(s.bounds) + ")"; },
           "A one-line summary.")
      .def_readonly("dem", &Seabed::dem, DOC(Seabed, dem))
      .def_readonly("bounds", &Seabed::bounds, DOC(Seabed, bounds))
      .def_readonly("smooth_region", &Seabed::smooth_region, DOC(Seabed, smooth_region));
  m.def("generate_seabed", &generate_seabed, py::arg("seed"), py::arg("options") = SeabedOptions{}, nogil,
        DOC(generate_seabed));

  py::class_<TideModel>(m, "TideModel", DOC(TideModel))
      .def(py::init([](double range, double duration, double t_low, const Interval& error) {
             return TideModel{range, duration, t_low, error};
           }),
           py::arg("range") = 5.2, py::arg("duration") = 22320.0, py::arg("t_low") = -5400.0,
           py::arg("error") = Interval(0.0),
           "Defaults: range 5.2 m, duration 22320 s, low water 5400 s before the start, no model error.")
      .def("__repr__", [](const TideModel& t) { return repr(t); }, "TideModel(range, duration, t_low).")
      .def_readwrite("range", &TideModel::range, DOC(TideModel, range))
      .def_readwrite("duration", &TideModel::duration, DOC(TideModel, duration))
      .def_readwrite("t_low", &TideModel::t_low, DOC(TideModel, t_low))
      .def_readwrite("error", &TideModel::error, DOC(TideModel, error))
      .def("__call__", &TideModel::operator(), py::arg("t"), DOC(TideModel, op_call))
      .def("height", &TideModel::height, py::arg("t"), DOC(TideModel, height))
      .def("height_value", &TideModel::height_value, py::arg("t"), DOC(TideModel, height_value));

  py::class_<BathymetrySensorBounds>(m, "BathymetrySensorBounds",
                                     DOC(BathymetrySensorBounds))
      .def(py::init<>(), "Defaults: DVL +-(0.2 % + 1 mm/s), INS +-0.05 deg, depth +-0.05 m, altitude +-(1 % + 5 cm), "
                         "tide +-0.1 m.")
      .def("__repr__", [](const BathymetrySensorBounds& b) { return repr(b); }, "A one-line summary.")
      .def_readwrite("dvl_scale", &BathymetrySensorBounds::dvl_scale, DOC(BathymetrySensorBounds, dvl_scale))
      .def_readwrite("dvl_offset", &BathymetrySensorBounds::dvl_offset, DOC(BathymetrySensorBounds, dvl_offset))
      .def_readwrite("heading", &BathymetrySensorBounds::heading, DOC(BathymetrySensorBounds, heading))
      .def_readwrite("attitude", &BathymetrySensorBounds::attitude, DOC(BathymetrySensorBounds, attitude))
      .def_readwrite("depth", &BathymetrySensorBounds::depth, DOC(BathymetrySensorBounds, depth))
      .def_readwrite("altitude_scale", &BathymetrySensorBounds::altitude_scale, DOC(BathymetrySensorBounds, altitude_scale))
      .def_readwrite("altitude_offset", &BathymetrySensorBounds::altitude_offset, DOC(BathymetrySensorBounds, altitude_offset))
      .def_readwrite("tide", &BathymetrySensorBounds::tide, DOC(BathymetrySensorBounds, tide))
      .def_readwrite("angle_accel", &BathymetrySensorBounds::angle_accel, DOC(BathymetrySensorBounds, angle_accel))
      .def_readwrite("velocity_accel2", &BathymetrySensorBounds::velocity_accel2,
                     DOC(BathymetrySensorBounds, velocity_accel2))
      .def_readwrite("speed_max", &BathymetrySensorBounds::speed_max, DOC(BathymetrySensorBounds, speed_max))
      .def_readwrite("beam_angle", &BathymetrySensorBounds::beam_angle, DOC(BathymetrySensorBounds, beam_angle))
      .def_readwrite("beam_spread", &BathymetrySensorBounds::beam_spread, DOC(BathymetrySensorBounds, beam_spread))
      .def_readwrite("beam_azimuth_spread", &BathymetrySensorBounds::beam_azimuth_spread,
                     DOC(BathymetrySensorBounds, beam_azimuth_spread));
  m.def("dvl_footprint", &dvl_footprint, py::arg("x"), py::arg("y"), py::arg("yaw"), py::arg("altitude"),
        py::arg("bounds") = BathymetrySensorBounds{}, DOC(dvl_footprint));
  m.def("footprint_depth", &footprint_depth, py::arg("dem"), py::arg("x"), py::arg("y"), py::arg("yaw"),
        py::arg("altitude"), py::arg("bounds") = BathymetrySensorBounds{},
        DOC(footprint_depth));
  m.def("footprint_filter_bound", &footprint_filter_bound, py::arg("seabed"), py::arg("cell"), py::arg("altitude_max"),
        py::arg("bounds") = BathymetrySensorBounds{},
        DOC(footprint_filter_bound));
  m.def("nadir_altitude_max", &nadir_altitude_max, py::arg("measured"), py::arg("seabed"), py::arg("cell"),
        py::arg("bounds") = BathymetrySensorBounds{}, DOC(nadir_altitude_max));
}

void init_bathymetry_mission(py::module_& m) {
  py::class_<BathymetryMissionOptions>(m, "BathymetryMissionOptions", DOC(BathymetryMissionOptions))
      .def(py::init<>(), "Defaults: 5760 s at 0.1 s, 1.03 m/s, 28 m turns, 40 m rails, 14.5 m depth.")
      .def("__repr__", &fields_repr, "Name(field=value, ...) of every field.")
      .def_readwrite("duration", &BathymetryMissionOptions::duration, DOC(BathymetryMissionOptions, duration))
      .def_readwrite("step", &BathymetryMissionOptions::step, DOC(BathymetryMissionOptions, step))
      .def_readwrite("speed", &BathymetryMissionOptions::speed, DOC(BathymetryMissionOptions, speed))
      .def_readwrite("turn_radius", &BathymetryMissionOptions::turn_radius, DOC(BathymetryMissionOptions, turn_radius))
      .def_readwrite("rail_spacing", &BathymetryMissionOptions::rail_spacing,
                     DOC(BathymetryMissionOptions, rail_spacing))
      .def_readwrite("depth", &BathymetryMissionOptions::depth, DOC(BathymetryMissionOptions, depth))
      .def_readwrite("transects", &BathymetryMissionOptions::transects, DOC(BathymetryMissionOptions, transects))
      .def_readwrite("tie_line_angle", &BathymetryMissionOptions::tie_line_angle,
                     DOC(BathymetryMissionOptions, tie_line_angle))
      .def_readwrite("seabed", &BathymetryMissionOptions::seabed, DOC(BathymetryMissionOptions, seabed))
      .def_readwrite("tide", &BathymetryMissionOptions::tide, DOC(BathymetryMissionOptions, tide))
      .def_readwrite("bounds", &BathymetryMissionOptions::bounds, DOC(BathymetryMissionOptions, bounds));
  m.def("bank_mission_options", &bank_mission_options, DOC(bank_mission_options));

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
      .def_property_readonly("seed", &Mission::seed, DOC(BathymetryMission, seed))
      .def_property_readonly("options", &Mission::options, DOC(BathymetryMission, options))
      .def_property_readonly("seabed", &Mission::seabed, DOC(BathymetryMission, seabed))
      .def_property_readonly("dem", &Mission::dem, DOC(BathymetryMission, dem))
      .def_property_readonly("bounds", &Mission::bounds, DOC(BathymetryMission, bounds))
      .def_property_readonly("tide", &Mission::tide, DOC(BathymetryMission, tide))
      .def_property_readonly("nb_samples", &Mission::nb_samples, DOC(BathymetryMission, nb_samples))
      .def_property_readonly("times", [](const Mission& x) { return array_of(x.times()); }, DOC(BathymetryMission, times))
      .def_property_readonly("x1", [](const Mission& x) { return array_of(x.x1()); }, DOC(BathymetryMission, x1))
      .def_property_readonly("x2", [](const Mission& x) { return array_of(x.x2()); }, DOC(BathymetryMission, x2))
      .def_property_readonly("truth", &Mission::truth, DOC(BathymetryMission, truth))
      .def_property_readonly("measured", &Mission::measured, DOC(BathymetryMission, measured))
      .def_property_readonly("tide_truth", [](const Mission& x) { return array_of(x.tide_truth()); },
                             DOC(BathymetryMission, tide_truth))
      .def_property_readonly("filtered_altitude", [](const Mission& x) { return array_of(x.filtered_altitude()); },
                             DOC(BathymetryMission, filtered_altitude))
      .def("path_length", &Mission::path_length, DOC(BathymetryMission, path_length))
      .def("tdomain", &Mission::tdomain, py::arg("dt"),
           DOC(BathymetryMission, tdomain))
      .def("sample_index", &Mission::sample_index, py::arg("t"), DOC(BathymetryMission, sample_index));

  m.def("bathymetry_sensor_tubes", &bathymetry_sensor_tubes, py::arg("mission"), py::arg("tdomain"), nogil,
        DOC(bathymetry_sensor_tubes));
  m.def("bathymetry_velocity_tube", &bathymetry_velocity_tube, py::arg("mission"), py::arg("tdomain"), nogil,
        DOC(bathymetry_velocity_tube));
  m.def("bathymetry_dead_reckoning", &bathymetry_dead_reckoning, py::arg("mission"), py::arg("tdomain"), py::arg("x0"),
        nogil, DOC(bathymetry_dead_reckoning));
  m.def("bathymetry_initial_box", &bathymetry_initial_box, py::arg("mission"), py::arg("horizontal") = 1.0,
        DOC(bathymetry_initial_box));
  m.def("bathymetry_observation_tube", &bathymetry_observation_tube, py::arg("mission"), py::arg("tdomain"), nogil,
        DOC(bathymetry_observation_tube));
  m.def("bathymetry_observation_rate_bound", &bathymetry_observation_rate_bound, py::arg("mission"),
        DOC(bathymetry_observation_rate_bound));
  m.def("bathymetry_truth", &bathymetry_truth, py::arg("mission"), DOC(bathymetry_truth));
  m.def("bathymetry_truth_observation", &bathymetry_truth_observation, py::arg("mission"),
        DOC(bathymetry_truth_observation));

  m.def("depth_colour", &depth_colour, py::arg("depth"), py::arg("lo"), py::arg("hi"),
        DOC(depth_colour));
  m.def("bathymetry_dem_figure", &bathymetry_dem_figure, py::arg("dem"), py::arg("x"), py::arg("y"),
        py::arg("title") = "Seabed DEM and path", py::arg("block") = 5.0, py::arg("width_px") = 600.0,
        DOC(bathymetry_dem_figure));
  m.def("bathymetry_map_figure", &bathymetry_map_figure, py::arg("mission"), py::arg("p"),
        py::arg("title") = "Mission map: dead reckoning and truth", py::arg("width_px") = 600.0,
        DOC(bathymetry_map_figure));
  m.def("bathymetry_observation_figure", &bathymetry_observation_figure, py::arg("mission"), py::arg("z"),
        py::arg("title") = "Observation tube [z](t) and truth", py::arg("width_px") = 700.0,
        DOC(bathymetry_observation_figure));
}

void init_range_observation(py::module_& m) {
  py::class_<RangeBounds>(m, "RangeBounds",
                          DOC(RangeBounds))
      .def(py::init<>(), "Defaults (plaza1): short 1.5 m, long 10 m, time stamps 0.2 s, speed 2 m/s.")
      .def(py::init<double, double, double, double>(), py::arg("short_err"), py::arg("long_err"),
           py::arg("time_err"), py::arg("speed"), "The four bounds.")
      .def("__repr__", [](const RangeBounds& b) { return repr(b); }, "RangeBounds(short_err, long_err, ...).")
      .def_readwrite("short_err", &RangeBounds::short_err, DOC(RangeBounds, short_err))
      .def_readwrite("long_err", &RangeBounds::long_err, DOC(RangeBounds, long_err))
      .def_readwrite("time_err", &RangeBounds::time_err, DOC(RangeBounds, time_err))
      .def_readwrite("speed", &RangeBounds::speed, DOC(RangeBounds, speed));
  m.def("range_observation_tubes", &range_observation_tubes, py::arg("tdomain"), py::arg("times"), py::arg("beacon"),
        py::arg("range"), py::arg("beacon_ids"), py::arg("bounds") = RangeBounds{}, nogil,
        DOC(range_observation_tubes));
}

}  // namespace

SILLAGE_BINDING(bathymetry, "figures", "interval", "tdomain", "trajectory", "tube") {
  init_bathymetry_data(m);
  init_bathymetry_mission(m);
  init_range_observation(m);
}

}  // namespace sillage::python
