#pragma once
// Temporary output files in flight, so that an interrupted run leaves none behind:
// write_image_atomic registers each one until it is renamed; a signal handler can unlink them
// all (async-signal-safe); a later run removes those a killed process left (dead PID in name).
#include <string>

namespace cgtmo::io {

// Name of the temporary for `target`: ".<stem>.cgtmo-tmp-<pid><ext>" in the same folder.
std::string temp_path_for(const std::string& target);

void register_temp(const std::string& path);
void unregister_temp(const std::string& path);

// Unlinks every registered temporary; only async-signal-safe calls (for signal handlers).
void unlink_registered_temps_signal_safe();

// Removes temporaries of `target` left by processes that no longer run. Returns how many.
int remove_stale_temps(const std::string& target);

}  // namespace cgtmo::io
