// Paper B's chords streamed to the board's 3-axis peripheral (window
// AXIS3) over the link: the queue is kept filled (never past its depth:
// the host counts the level of the last reply and the chords in flight),
// RUN is set once the queue is full, DRAIN after the last chord; positions
// come back in every reply; a tripped watchdog is reported and resumed; a
// stop request brings the motion to rest along its path (feed hold) and
// then stops. Transport-agnostic: `contour stream` runs it on a serial
// port, the tests on the simulated board.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "link_client.hpp"

namespace contour::board {

struct Chord3 {
  std::int64_t dx = 0, dy = 0, dz = 0;
};

struct StreamConfig {
  double clock_hz = 12e6;             // the board's clock
  double cycle_s = 1e-3;              // the control cycle of the chords
  std::uint32_t step_len = 12;        // STEP high, clocks (1 us)
  std::uint32_t step_space = 12;      // STEP low between steps, clocks
  std::uint32_t wdog_clocks = 600000;  // 50 ms
  std::size_t chords_per_frame = 11;  // fits MAX_FRAME with packed chords
  double rest_s = 10;                 // a feed hold must bring the board to rest within this (transport clock)
};

struct Progress {
  std::size_t sent = 0, total = 0;
  std::array<std::int64_t, 3> pos{};  // the position of the latest reply (every reply carries it)
  unsigned level = 0;
  std::uint64_t replies = 0;
};

struct StreamResult {
  std::array<std::int64_t, 3> start{}, end{}, expected{};
  std::uint32_t chords = 0;      // chords the board loaded in this run
  std::uint32_t underruns = 0;
  std::uint32_t wdog_trips = 0;
  bool stopped = false;          // ended by a stop request
  LinkStats link;
};

// Throws LinkError (no answer, an error reply, not a contour board) and
// std::invalid_argument for a chord the board cannot take (named by index).
StreamResult stream_chords(LinkClient& link, Transport& t, const std::vector<Chord3>& chords, const StreamConfig& cfg,
                           const std::function<void(const Progress&)>& progress = {},
                           const std::atomic<bool>* stop = nullptr);

// The board's identity registers, checked: throws LinkError naming what
// answered instead.
void check_board(LinkClient& link);

}  // namespace contour::board
