// The one channel through which the library speaks to the user, besides its results and its errors:
// - notes ("glossy: X: 12 of 1458000 bins unmeasured") that code reading input wants printed. They are held
//   back until the command knows its input is good, so that a run refused as bad input prints its error as
//   its only stderr line (exit status 2), and a run that goes on prints them before its work;
// - progress ("glossy: [3/300] … done; 40 s elapsed"): told at once, each line whole.
// The command line prints both to stderr; the Python module turns notes into warnings and leaves progress on
// stderr, where a long job's user looks for it. Thread-safe.
#pragma once

#include <string>
#include <vector>

namespace glossy {

// Queues one line; "glossy: " is put in front when printed.
void note(std::string line);
// Queues the line unless this process queued the same line before: a fact about an input (a MERL table's
// unmeasured bins) is told once a run, not once for every sheet that reads the input.
void noteOnce(std::string line);
// Prints the queued lines to stderr, in order, and forgets them.
void flushNotes();
// Forgets the queued lines (the run failed on bad input: its error is the one line).
void discardNotes();
// Hands the queued lines over, without "glossy: ", and forgets them: for a caller that tells the user its own
// way (the Python module turns them into warnings).
std::vector<std::string> takeNotes();
// From now on flushNotes() keeps the lines queued for takeNotes(): the Python module's notes are warnings.
void keepNotesForTaking();

// Prints one line of progress now, as it is (with its own "glossy: " or "glossy study: "), whole even when
// threads tell at once.
void tell(const std::string& line);

}  // namespace glossy
