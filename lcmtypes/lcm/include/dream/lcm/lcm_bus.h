#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <regex>
#include <string>
#include <unordered_map>
#include <vector>

#include "dream/lcm/lcm_interface.h"
#include "dream/lcm/udpm_receive_socket.h"

struct _lcm_t;  // LCM's C instance (lcm_t)

namespace lcm {
class LCM;
class ReceiveBuffer;
class Subscription;
}  // namespace lcm

namespace dream::lcm {

/// The real transport: an lcm::LCM opened on a URL chosen by the user.
///
/// The bus holds exactly one LCM subscription, whose regex is the union of
/// its handlers' ones, and routes each message to the handlers whose regex
/// matches its channel. LCM 1.3.1 counts queued messages per subscription,
/// and packets left over from its udpm start-up self test throw those counts
/// off, so with several overlapping LCM subscriptions one of them could
/// silently miss a message another received (the run log lacked a command
/// the simulator acted on). One subscription cannot disagree with itself, and
/// the self test runs when the bus opens, before any handler subscribes.
///
/// Its queue capacity is raised (LCM's default of 30 silently drops messages
/// when a lockstep step delivers one command per robot), and udpm URLs get a
/// 4 MB kernel receive buffer unless the URL sets one (see ResolveLcmUrl()).
///
/// On `memq://` (everything in this process: `dream run`) the bus queues
/// messages itself, with LCM's memq semantics (first in, first out; a message
/// no handler wants when it is published is dropped; kQueueCapacity), instead
/// of going through LCM's memq provider, which costs three system calls per
/// message (a notification pipe written, polled and read): half of an
/// embedded run's loop. Once c_handle() hands LCM's instance to another host
/// (the embedded Python agents), messages go through LCM again, so that host
/// hears them; what was queued by then is passed on first, in order.
///
/// On udpm the bus puts a ChannelPrefixFilter on LCM's receive socket, kept
/// to its handlers' regexes, so the kernel drops datagrams on channels no
/// handler can match instead of waking LCM's receive thread for each (an
/// agent would wake for every other robot's command). A handler of ".*" (the
/// simulator's) lifts it, and so does c_handle(): another host subscribes
/// behind the bus's back.
class LcmBus final : public LcmInterface {
 public:
  /// Messages queued before LCM drops new ones; enough for several steps of
  /// 128 robots' commands and radio traffic (a sim_only run's most).
  static constexpr int kQueueCapacity = 10000;

  /// Opens LCM on `url` as given (use ResolveLcmUrl() to apply defaults).
  /// @throws std::runtime_error naming the URL when LCM cannot open it.
  explicit LcmBus(std::string url);
  ~LcmBus() override;

  LcmBus(const LcmBus&) = delete;
  LcmBus& operator=(const LcmBus&) = delete;

  void Publish(const std::string& channel, const void* data, int size) override;
  /// @throws std::invalid_argument naming `channel_regex` when it is not a regex.
  Subscription Subscribe(const std::string& channel_regex, RawHandler handler) override;
  int HandleSubscriptions(int timeout_ms) override;
  const std::string& url() const override { return url_; }
  long handler_failures() const override { return handler_failures_; }
  long dropped_messages() const override { return queue_overflows(); }
  /// Channels whose routes are cached; beyond it, routes are matched per message.
  static constexpr size_t kMaxRoutedChannels = 1024;
  /// Messages delivered on channels past kMaxRoutedChannels (made-up names, usually).
  long uncached_deliveries() const { return uncached_deliveries_; }
  /// LCM's C instance under this bus, for a host in another language in this
  /// process (the Python agents of `dream run`, dream::python_host) to
  /// subscribe and publish on the same queue. It stays this bus's: never
  /// destroy it. From then on a memq bus publishes through LCM too.
  _lcm_t* c_handle();
  /// Messages a memq bus's own queue refused because it held kQueueCapacity.
  long queue_overflows() const;
  /// The channel prefixes the kernel lets through to this bus (udpm); empty
  /// when it filters nothing.
  const std::vector<std::string>& kernel_filter_prefixes() const { return kernel_filter_prefixes_; }

 private:
  struct Subscriber {
    std::regex channel_regex;  // matched against the whole channel name, as LCM does
    std::string channel_regex_text;
    RawHandler handler;
    bool active = true;  // false once its Subscription is gone; kept so indices stay valid
  };
  /// Where the bus listens before any handler subscribes; nobody publishes there.
  static constexpr const char* kStartUpChannel = "DREAM_LCMBUS_STARTING";
  static void Dispatch(const ::lcm::ReceiveBuffer* buffer, const std::string& channel, LcmBus* bus);
  void Deliver(const std::string& channel, const void* data, int size);
  void Unsubscribe(size_t index);
  std::vector<size_t> MatchSubscribers(const std::string& channel) const;
  void DiscardStartUpLeftovers();
  void ResubscribeForAllHandlers();
  void UpdateKernelFilter();
  const std::vector<size_t>& RouteOf(const std::string& channel, std::vector<size_t>* uncached);
  int HandleOwnQueue(int timeout_ms);
  void PassOwnQueueToLcm();

  /// A message on a memq bus's own queue.
  struct Queued {
    std::string channel;
    std::vector<uint8_t> bytes;
  };

  std::string url_;
  // Before lcm_: notes the sockets open before LCM opens its own.
  UdpmReceiveSocket receive_socket_{url_};
  std::unique_ptr<::lcm::LCM> lcm_;
  int receive_fd_ = -1;                // LCM's udpm receive socket, when found
  bool kernel_filter_allowed_ = true;  // false once c_handle() handed LCM out
  std::vector<std::string> kernel_filter_prefixes_;
  ::lcm::Subscription* subscription_ = nullptr;  // owned by lcm_
  // deque: a handler may subscribe while it runs; its own element must not move.
  std::deque<Subscriber> subscribers_;
  // channel -> indices into subscribers_; a run uses few channels, so regexes
  // are matched once per channel, not once per message. Capped at
  // kMaxRoutedChannels: names come from the network.
  std::unordered_map<std::string, std::vector<size_t>> routes_;
  long handler_failures_ = 0;
  long uncached_deliveries_ = 0;
  // The memq bus's own queue (own_queue_ while no other host uses LCM's
  // instance). The mutex keeps Publish as thread-safe as LCM's; it also
  // guards routes_ and subscribers_ while the own queue is in use.
  bool own_queue_ = false;
  mutable std::mutex queue_mutex_;
  std::condition_variable queue_filled_;
  std::deque<Queued> queue_;
  long queue_overflows_ = 0;
  // Handlers running now (Deliver nests when a handler handles); a handler
  // unsubscribed meanwhile is released once none runs, never while it runs.
  int delivering_ = 0;
  std::vector<size_t> unsubscribed_while_delivering_;
  // What the Subscriptions hold on to: expired once the bus is gone.
  std::shared_ptr<LcmBus*> self_ = std::make_shared<LcmBus*>(this);
};

}  // namespace dream::lcm
