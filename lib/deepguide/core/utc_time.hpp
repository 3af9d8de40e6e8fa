#pragma once
// Times at the interfaces are ISO 8601 in UTC; this is where the whole
// library reads and writes them.
//
// Read: YYYY-MM-DD[(T|t| )hh:mm[:ss[(.|,)f...]]][ ][Z|z|UTC|GMT|(+|-)hh[[:]mm]],
// surrounding blanks ignored, fields with or without leading zeros (CF's
// reference dates are written "days since 1950-1-1 0:0:0"). The calendar is
// checked with std::chrono: no 30 February, no hour 24 (ISO 8601-1:2019
// dropped 24:00), a leap second's :60 taken. GDAL's OGRParseDate is not used for this: it accepts
// "2024-05-01T12:30:00Zjunk" and 30 February, and drops the zone of
// "12:30Z" and of " UTC".

#include <optional>
#include <string>
#include <string_view>

#include "deepguide/core/api.hpp"

namespace DEEPGUIDE_API deepguide {

/// Seconds since 1970-01-01T00:00:00Z; nullopt for anything else, and for a
/// time without a zone when `zone_required` (a clock of an unknown place).
/// Without a zone, and with `zone_required` false, the time is UTC (CF).
std::optional<double> parse_iso8601(std::string_view text, bool zone_required);

/// The same for a time the user gave as `what` (an option, a field), which
/// needs no zone: InputError "WHAT: expected a UTC time such as
/// 2019-03-07T15:00:00Z, got 'TEXT'" otherwise.
double parse_utc(const std::string& text, const std::string& what);

/// "YYYY-MM-DDThh:mm:ssZ" rounded to the second; with `millis`, rounded to
/// the millisecond, with ".fff" when that is not a whole second. "?" for a
/// time that is not finite.
std::string format_utc(double epoch_s, bool millis = false);

}  // namespace deepguide
