// One plain base-protocol transaction, as the platform's initiators (the ROP's DMA, the host)
// build every one: no byte enables, no streaming, no DMI hint, the response incomplete.
#pragma once

#include <cstddef>
#include <cstdint>

#include <tlm>

namespace zb::vp {

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

}  // namespace zb::vp
