#pragma once
// Lock-free single-producer / single-consumer "latest value" exchange.
#include <atomic>
#include <cstdint>

namespace geoshaping::haptics
{

// Three slots: the writer owns `back`, the reader owns `front`, the third sits in the
// middle. publish() swaps back and middle in one atomic exchange and marks the middle
// fresh; update() swaps front and middle only if the middle is fresh. Each slot is owned
// by exactly one side at any time, so
//  - a reader never sees a half-written value (no torn reads, even of a std::vector);
//  - neither side ever waits, spins or retries: one atomic exchange per publish/update;
//  - the reader gets the latest complete value; values published in between are
//    dropped, which is what a 1 kHz consumer of 60 Hz state (or the reverse) wants.
// The exchange is acq_rel, so everything the writer wrote into the slot before publish()
// happens-before the reader's use of it after update().
//
// Chosen over a seqlock because the scene snapshot holds a triangle vector: a seqlock
// reader copies while the writer may reallocate it (undefined behaviour), and its retry
// loop can make the servo thread wait. The cost is three copies of T; assigning into the
// back slot reuses its capacity, so steady-state publishing does not allocate.
//
// Exactly one writer thread and one reader thread; they may be different from the
// thread that constructed the buffer.
template<class T>
class TripleBuffer
{
public:
  TripleBuffer() = default;
  explicit TripleBuffer(const T& initial)
  {
    for (Slot& s : slots_)
      s.value = initial;
  }

  // Writer: fill back() completely, then publish(). back() holds an older value (the one
  // the reader gave up), never the one just published.
  T& back() { return slots_[back_].value; }
  void publish() { back_ = middle_.exchange(back_ | fresh, std::memory_order_acq_rel) & index; }
  void write(const T& value)
  {
    back() = value;
    publish();
  }

  // Reader: take the newest published value if there is one; true if front() changed.
  bool update()
  {
    if ((middle_.load(std::memory_order_relaxed) & fresh) == 0)
      return false;
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & index;
    return true;
  }
  const T& front() const { return slots_[front_].value; }

private:
  static constexpr std::uint8_t index = 0x3;
  static constexpr std::uint8_t fresh = 0x4;

  // Slots on separate cache lines so the two threads do not false-share.
  struct alignas(64) Slot
  {
    T value;
  };
  Slot slots_[3]{};
  alignas(64) std::atomic<std::uint8_t> middle_{ 1 };
  alignas(64) std::uint8_t back_ = 0;
  alignas(64) std::uint8_t front_ = 2;
};

} // namespace geoshaping::haptics
