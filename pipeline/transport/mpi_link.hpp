#pragma once
// Sending and polling farm messages over MPI_COMM_WORLD.  Polling never
// blocks: a rank waiting for messages must sleep between polls (a rank
// blocked in MPI_Recv spins a whole core).

#include <memory>
#include <optional>
#include <vector>

#include "transport/mpi_messages.hpp"

namespace lc::farm {

struct Message {
  int source = 0;
  Tag tag = Tag::stop;
  Bytes data;
};

// Sends `data` to `dest` (returns when the buffer may be reused).
void mpi_send(int dest, Tag tag, const Bytes& data);
// Messages on their way out without waiting for the receiver: a large
// message (a stripe's pixels) is only delivered once the master receives
// it, and a worker that waited for that would idle through the master's
// sleep.  Messages to one destination still arrive in posting order.
class SendQueue {
 public:
  SendQueue();
  ~SendQueue();  // waits for everything posted (MPI needs them complete before finalising)
  SendQueue(const SendQueue&) = delete;
  SendQueue& operator=(const SendQueue&) = delete;

  void post(int dest, Tag tag, Bytes data);
  // Lets MPI move pending messages along; frees the delivered ones.
  void progress();
  bool empty() const { return pending_.empty(); }
  // Waits (polling, sleeping between polls) until everything is delivered.
  void drain();

 private:
  struct Pending;
  std::vector<std::unique_ptr<Pending>> pending_;
};

// Receives one message from `source` (MPI_ANY_SOURCE for any) if one has
// arrived; nullopt at once otherwise.
std::optional<Message> mpi_poll(int source);

}  // namespace lc::farm
