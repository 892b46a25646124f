#include "link_client.hpp"

#include <cstdio>

namespace contour::board {

namespace {

constexpr unsigned kMaxLenRefusals = 16;  // LEN refusals in a row before the host gives up

std::size_t count_reads(const std::vector<Op>& ops) {
  std::size_t n = 0;
  for (const Op& o : ops) n += o.write ? 0 : 1;
  return n;
}

bool has_write(const std::vector<Op>& ops) { return count_reads(ops) != ops.size(); }

}  // namespace

LinkClient::LinkClient(Transport& t, LinkTimes times) : t_(t), times_(times) { last_valid_ = t_.now_s(); }

std::size_t LinkClient::chords_in_flight() const {
  std::size_t n = 0;
  for (const Frame& f : out_) n += f.chords;
  return n;
}

void LinkClient::send(Frame& f) {
  f.gen = gen_;
  f.sent_at = t_.now_s();
  t_.write(f.bytes);
  ++stats_.frames;
}

void LinkClient::go_back() {
  ++gen_;
  ++stats_.go_backs;
  for (Frame& f : out_) {
    send(f);
    ++stats_.resends;
  }
}

void LinkClient::check_dead() {
  if (t_.now_s() - last_valid_ <= times_.dead_s) return;
  char b[96];
  std::snprintf(b, sizeof b, "the board does not answer (no valid reply for %g s, %llu frames sent)", times_.dead_s,
                static_cast<unsigned long long>(stats_.frames));
  throw LinkError(b);
}

// A LEN refusal: the host's frames are always of a legal length, so one on
// the wire was cut or merged with the next (a dropped END byte): sent again
// like a CRC refusal. Many in a row, with no OK reply between, are the
// host's own error and end the run.
void LinkClient::refuse_len(const Reply& r, std::uint8_t seq) {
  if (++len_refusals_ <= kMaxLenRefusals) return;
  throw LinkError("the board refused frame " + std::to_string(seq) + ": " + status_name(r.status) + " at byte " +
                  std::to_string(r.detail) + " (" + std::to_string(kMaxLenRefusals) + " times in a row)");
}

// A valid reply: everything before the board's next expected number is
// done; a SEQ refusal of a frame sent since the last go-back starts another.
void LinkClient::handle(const Reply& r) {
  last_valid_ = t_.now_s();
  last_ = r;
  if (on_reply) on_reply(r);
  if (r.flag(BOARD_FLAG_REJECT))
    throw LinkError("the board refused a chord or block: its queue was full (STATUS.REJECT)");
  if (r.status == BOARD_ERR_REG)
    throw LinkError("the board refused frame " + std::to_string(r.seq) + ": " + status_name(r.status) +
                    " at byte " + std::to_string(r.detail));
  if (r.status == BOARD_ERR_LEN) refuse_len(r, r.seq);
  if (r.status == BOARD_ERR_OK) len_refusals_ = 0;
  if (r.status != BOARD_ERR_OK) ++stats_.refused;
  bool stale = true;
  for (const Frame& f : out_)
    if (f.seq == r.seq) {
      stale = f.gen != gen_;
      if (r.status == BOARD_ERR_OK && f.reads != 0 && f.reads == r.data.size() && on_data) on_data(r);
    }
  while (!out_.empty() && before(out_.front().seq, r.next_seq)) out_.pop_front();
  if (r.status == BOARD_ERR_SEQ && !out_.empty() && !stale) go_back();
}

void LinkClient::pump(double timeout_s) {
  const Bytes in = t_.read(timeout_s);
  for (std::uint8_t c : in) {
    auto f = dec_.feed(c);
    if (!f) continue;
    auto r = dec_.last_bad() ? std::nullopt : parse_reply(*f);
    if (!r) {
      ++stats_.bad_replies;
      continue;
    }
    handle(*r);
  }
  if (!out_.empty() && t_.now_s() - out_.front().sent_at > times_.resend_s) go_back();
  check_dead();
}

void LinkClient::post(const std::vector<Op>& ops, std::size_t chords) {
  if (!has_write(ops)) throw std::logic_error("LinkClient::post: a frame of reads only");
  Frame f;
  f.seq = next_seq_++;
  f.bytes = make_request(f.seq, ops);
  f.reads = count_reads(ops);
  f.chords = chords;
  out_.push_back(f);
  send(out_.back());
}

void LinkClient::drain() {
  while (!out_.empty()) pump(0.002);
}

void LinkClient::sync(std::uint8_t word) {
  next_seq_ = last_.next_seq;
  const Reply r = transact({Op{false, word, 0}});
  next_seq_ = r.next_seq;
}

Reply LinkClient::transact(const std::vector<Op>& ops) {
  drain();
  const bool writes = has_write(ops);
  const std::uint8_t seq = writes ? next_seq_++ : next_seq_;
  const std::size_t reads = count_reads(ops);
  const Bytes bytes = make_request(seq, ops);
  for (;;) {
    t_.write(bytes);
    ++stats_.frames;
    const double sent = t_.now_s();
    bool again = false;
    while (!again && t_.now_s() - sent < times_.resend_s) {
      for (std::uint8_t c : t_.read(0.002)) {
        auto f = dec_.feed(c);
        auto r = (f && !dec_.last_bad()) ? parse_reply(*f) : std::nullopt;
        if (f && !r) ++stats_.bad_replies;
        if (!r || r->seq != seq) continue;
        if (auto done = transact_reply(*r, seq, writes, reads))
          return done->status == BOARD_ERR_DUP && reads != 0 ? transact(reads_of(ops)) : *done;
        again = true;  // refused (CRC): send again
      }
      check_dead();
    }
    ++stats_.resends;
  }
}

// The read ops of a frame, in order: sent alone when the frame's writes
// were done but its reply, with the reads' data, was lost (a DUP reply
// carries no data).
std::vector<Op> LinkClient::reads_of(const std::vector<Op>& ops) {
  std::vector<Op> r;
  for (const Op& op : ops)
    if (!op.write) r.push_back(op);
  return r;
}

// The reply to transact's frame: the reply if it is done, nothing if it
// must be sent again; throws what no resend mends.
std::optional<Reply> LinkClient::transact_reply(const Reply& r, std::uint8_t seq, bool writes, std::size_t reads) {
  last_valid_ = t_.now_s();
  last_ = r;
  if (on_reply) on_reply(r);
  if (r.status == BOARD_ERR_OK && r.data.size() == reads) return r;
  if (r.status == BOARD_ERR_DUP && writes) return r;
  if (r.status == BOARD_ERR_SEQ && writes)
    throw LinkError("sequence out of step: the board expects frame " + std::to_string(r.next_seq) +
                    ", the host sent " + std::to_string(seq) + " (was the board reset?)");
  if (r.status == BOARD_ERR_REG)
    throw LinkError("the board refused frame " + std::to_string(seq) + ": " + status_name(r.status) + " at byte " +
                    std::to_string(r.detail));
  if (r.status == BOARD_ERR_LEN) refuse_len(r, seq);
  ++stats_.refused;
  return std::nullopt;
}

}  // namespace contour::board
