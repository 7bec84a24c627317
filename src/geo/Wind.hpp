#pragma once
// The 10 m wind: one type from the command line to the shader. Directions are named for the way
// they point: `towards` (where the air moves, the physics' and the shaders' convention) or
// `from` (where it comes from, the meteorological convention of the flags and scene files).
//   --wind SPEED[,FROM] and [ocean] wind_from_deg  ->  Wind (towards)  ->  WindVector (u, v)
#include <string>

namespace og::geo {

/// A horizontal wind vector, m/s: eastward (u) and northward (v) components, pointing where the
/// air moves (like the u/v of wind files).
struct WindVector {
  double uMs = 0.0;
  double vMs = 0.0;
};

/// A wind as a speed and the direction it blows towards.
struct Wind {
  double speedMs = 7.0;      ///< 10 m wind speed, m/s, [0, 50]
  double towardsDeg = 90.0;  ///< where it blows towards, degrees clockwise from north, [0, 360)

  /// The wind of a meteorological report: `fromDeg` is where it comes from, clockwise from
  /// north (270 = a westerly, blowing towards 90, the east).
  static Wind blowingFrom(double speedMs, double fromDeg);
  static Wind blowingTowards(double speedMs, double towardsDeg);
  /// The wind of a vector; a calm (0, 0) blows towards 0.
  static Wind ofVector(WindVector w);

  /// Where it comes from, degrees clockwise from north, [0, 360).
  [[nodiscard]] double fromDeg() const;
  /// u = speed·sin(towards), v = speed·cos(towards).
  [[nodiscard]] WindVector vector() const;
};

/// The one reading of `--wind SPEED[,FROM]`: m/s and where it comes from, degrees clockwise
/// from north (`defaultFromDeg` when left out). Throws og::InputError "--wind: ..." for text
/// that is not one or two numbers, a speed outside [0, 50] m/s or a direction outside
/// [-720, 720] degrees.
Wind parseWindFlag(const std::string& text, double defaultFromDeg);

}  // namespace og::geo
