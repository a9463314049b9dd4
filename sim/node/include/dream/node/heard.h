#pragma once

namespace dream::node {

/// What became of a message SimNode heard on the bus.
enum class Heard {
  kUsed,     ///< part of the run: recorded
  kRefused,  ///< counted in bad_messages, kept out of the log (RefusedRecord)
  kRepeat,   ///< a repeat of what the run took already (a resent command or radio, a second fault) or a late one:
             ///< neither
};

}  // namespace dream::node
