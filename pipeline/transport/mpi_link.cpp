#include "transport/mpi_link.hpp"

#include <chrono>
#include <thread>

#include <mpi.h>

namespace lc::farm {

void mpi_send(int dest, Tag tag, const Bytes& data) {
  MPI_Send(data.data(), static_cast<int>(data.size()), MPI_BYTE, dest, static_cast<int>(tag), MPI_COMM_WORLD);
}

struct SendQueue::Pending {
  Bytes data;
  MPI_Request request = MPI_REQUEST_NULL;
};

SendQueue::SendQueue() = default;
SendQueue::~SendQueue() { drain(); }

void SendQueue::post(int dest, Tag tag, Bytes data) {
  auto p = std::make_unique<Pending>();
  p->data = std::move(data);
  MPI_Isend(p->data.data(), static_cast<int>(p->data.size()), MPI_BYTE, dest, static_cast<int>(tag), MPI_COMM_WORLD,
            &p->request);
  pending_.push_back(std::move(p));
}

void SendQueue::progress() {
  std::erase_if(pending_, [](const std::unique_ptr<Pending>& p) {
    int done = 0;
    MPI_Test(&p->request, &done, MPI_STATUS_IGNORE);
    return done != 0;
  });
}

void SendQueue::drain() {
  for (progress(); !pending_.empty(); progress()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

std::optional<Message> mpi_poll(int source) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  Message m;
  m.source = status.MPI_SOURCE;
  m.tag = static_cast<Tag>(status.MPI_TAG);
  m.data.resize(static_cast<std::size_t>(count));
  MPI_Recv(m.data.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

}  // namespace lc::farm
