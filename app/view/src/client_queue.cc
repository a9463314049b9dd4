#include "dream/view/client_queue.h"

#include <stdexcept>
#include <utility>

namespace dream::view {

ClientQueue::ClientQueue(size_t capacity) : capacity_(capacity) {
  if (capacity_ == 0) throw std::invalid_argument("ClientQueue: capacity must be at least 1");
}

void ClientQueue::Push(Message message) {
  if (messages_.size() >= capacity_) {
    messages_.pop_front();
    ++dropped_;
  }
  messages_.push_back(std::move(message));
}

ClientQueue::Message ClientQueue::Pop() {
  if (messages_.empty()) return nullptr;
  Message front = std::move(messages_.front());
  messages_.pop_front();
  return front;
}

}  // namespace dream::view
