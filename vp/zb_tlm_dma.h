// The platform's initiators' memory traffic (the ROP's DMA, the host): one plain base-protocol
// transaction builder, and a port that moves bytes through DMI where the target grants it, else
// in bursts of b_transport, its time into the initiator's quantum keeper.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <tlm>
#include <tlm_utils/tlm_quantumkeeper.h>

namespace zb::vp {

// No byte enables, no streaming, no DMI hint, the response incomplete.
inline void set_payload(tlm::tlm_generic_payload& tx, tlm::tlm_command cmd, uint64_t addr,
                        void* data, size_t len) {
  tx.set_command(cmd);
  tx.set_address(addr);
  tx.set_data_ptr(static_cast<unsigned char*>(data));
  tx.set_data_length(unsigned(len));
  tx.set_streaming_width(unsigned(len));
  tx.set_byte_enable_ptr(nullptr);
  tx.set_dmi_allowed(false);
  tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
}

// TLM_ADDRESS_ERROR_RESPONSE and the like, for messages.
inline std::string response_text(tlm::tlm_response_status r) {
  tlm::tlm_generic_payload tx;
  tx.set_response_status(r);
  return tx.get_response_string();
}

struct DmaCounts {
  uint64_t bytes = 0;         // moved, both ways
  uint64_t transactions = 0;  // b_transport calls (DMI accesses not counted)
  uint64_t dmi_accesses = 0, dmi_grants = 0, dmi_invalidations = 0;
};

class DmaPort {
 public:
  // `burst`: bytes a b_transport moves at most; `use_dmi`: ask for and use DMI pointers.
  DmaPort(uint32_t burst, bool use_dmi) : burst_(burst), use_dmi_(use_dmi) {}

  // Moves `len` bytes between `data` and memory at `addr` through `fw`. A DMI access is timed
  // as a burst of 8-byte beats at the DMI latency; a b_transport's delay is the target's. An
  // error response stops it: returned, `failed` set to that burst's address.
  tlm::tlm_response_status access(tlm::tlm_fw_transport_if<>& fw, tlm_utils::tlm_quantumkeeper& qk,
                                  tlm::tlm_command cmd, uint64_t addr, uint8_t* data, size_t len,
                                  uint64_t& failed);
  // Memory [addr, addr + len) in place, for `cmd`, through a DMI pointer held or asked for now;
  // null where DMI is off or not granted over the whole range. The pointer is good until the
  // initiator next waits (an invalidation may come then): it syncs first, if the quantum asks,
  // never after. The caller charges the bytes it moves through it.
  uint8_t* view(tlm::tlm_fw_transport_if<>& fw, tlm_utils::tlm_quantumkeeper& qk,
                tlm::tlm_command cmd, uint64_t addr, size_t len);
  // `len` bytes moved through a view: timed and counted as access() times a DMI access.
  void charge(tlm_utils::tlm_quantumkeeper& qk, tlm::tlm_command cmd, size_t len);
  // The target's backward call: a pointer overlapping [start, end] is dropped.
  void invalidate(uint64_t start, uint64_t end);
  const DmaCounts& counts() const { return counts_; }

 private:
  // The held pointer at `addr` when it covers [addr, addr + len) for `cmd`, else null.
  uint8_t* held(tlm::tlm_command cmd, uint64_t addr, size_t len) const;
  void ask_dmi(tlm::tlm_fw_transport_if<>& fw, tlm::tlm_command cmd, uint64_t addr);

  uint32_t burst_;
  bool use_dmi_;
  tlm::tlm_dmi dmi_;  // the pointer granted last (one at a time)
  bool dmi_valid_ = false;
  DmaCounts counts_;
};

}  // namespace zb::vp
