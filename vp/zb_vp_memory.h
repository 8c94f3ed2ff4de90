// The example platform's memory (docs/systemc.md "zblend_vp"): a byte array behind a TLM-2.0
// target socket, with a latency a transaction and a beat, DMI over all of it, transport_dbg.
#pragma once

#include <cstdint>
#include <memory>

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>

namespace zb::vp {

struct MemoryOptions {
  uint64_t bytes = 64u << 20;
  sc_core::sc_time access{20, sc_core::SC_NS};  // a transaction's first beat
  sc_core::sc_time beat{1, sc_core::SC_NS};     // each 8-byte beat
  bool dmi = true;                              // grant DMI
};

class ZbVpMemory : public sc_core::sc_module {
 public:
  // Any number of initiators (the host, the ROP) bind here.
  tlm_utils::multi_passthrough_target_socket<ZbVpMemory> socket;

  ZbVpMemory(sc_core::sc_module_name name, const MemoryOptions& options = {});

  // Takes back every DMI pointer granted (as a memory remapped would); counts the calls.
  void invalidate_dmi();
  uint8_t* data() { return mem_.get(); }  // a backdoor for tests; not for platform traffic
  uint64_t size() const { return bytes_; }
  uint64_t transactions() const { return transactions_; }

 private:
  void b_transport(int port, tlm::tlm_generic_payload& tx, sc_core::sc_time& delay);
  unsigned transport_dbg(int port, tlm::tlm_generic_payload& tx);
  bool get_direct_mem_ptr(int port, tlm::tlm_generic_payload& tx, tlm::tlm_dmi& dmi);

  MemoryOptions options_;
  // Mapped anonymous: zero pages, touched only where written, in huge pages where the system
  // gives them (fewer faults when a frame is written).
  struct Unmap {
    uint64_t bytes;
    void operator()(uint8_t* p) const;
  };
  std::unique_ptr<uint8_t, Unmap> mem_;
  uint64_t bytes_;
  uint64_t transactions_ = 0;
};

}  // namespace zb::vp
