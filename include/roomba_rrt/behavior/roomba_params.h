// The Roomba behaviour's parameters (the lab's constants), shared by the FSM and the BT.
#pragma once

#include <cmath>
#include <string>

namespace roomba_rrt::behavior {

/// The lab's constants (CT-213 lab 1) as defaults; config/roomba_behavior.yaml documents them.
/// Times are in seconds and are turned into tick counts at `rate`: a motion that lasts T seconds
/// executes round(T·rate) ticks (MoveForward 180, MoveInSpiral 1200, GoBack 30 at 60 Hz).
struct RoombaParams {
  double move_forward_time = 3.0;      ///< s
  double move_in_spiral_time = 20.0;   ///< s
  double go_back_time = 0.5;           ///< s
  double forward_speed = 0.5;          ///< m/s, MoveForward and MoveInSpiral
  double backward_speed = -0.1;        ///< m/s, GoBack (negative: backwards)
  double angular_speed = 0.5;          ///< rad/s, Rotate
  double initial_radius_spiral = 0.2;  ///< m, r0 of the spiral r(t) = r0 + b·t
  double spiral_factor = 0.05;         ///< m/s, b of the spiral
  double rate = 60.0;                  ///< ticks per second; the sample time is 1 / rate

  double sampleTime() const { return 1.0 / rate; }
  /// Number of ticks that `seconds` last at `rate`.
  long ticks(double seconds) const { return std::lround(seconds * rate); }
};

/// The supported ranges: they keep tick counts within `long` and the node's timer sane.
struct RoombaParamLimits {
  static constexpr double kMaxTime = 1e6;    ///< every *_time in [0, 1e6] s
  static constexpr double kMaxSpeed = 100;   ///< |speeds| in (0, 100] m/s or rad/s
  static constexpr double kMaxSpiral = 1e3;  ///< initial_radius_spiral (0, 1e3] m, factor [0, 1e3]
  static constexpr double kMinRate = 1;      ///< rate in [1, 1000] Hz
  static constexpr double kMaxRate = 1000;
};

/// Throws util::InvalidInput naming the first bad field (e.g. "angular_speed: must be in
/// (0, 100], got 0"): non-finite values, values outside RoombaParamLimits, speeds of the wrong
/// sign.
void validate(const RoombaParams& params);

/// Reads the parameters from a YAML file (format: config/roomba_behavior.yaml); missing keys keep
/// the defaults. Throws util::InvalidInput naming the file and the bad key for an unreadable
/// file, a non-number, an unknown key, or values that fail validate().
RoombaParams loadRoombaParams(const std::string& yaml_path);

/// Same, from YAML text; `source` names it in error messages.
RoombaParams parseRoombaParams(const std::string& yaml_text,
                               const std::string& source = "<string>");

}  // namespace roomba_rrt::behavior
