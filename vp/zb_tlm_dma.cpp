#include "zb_tlm_dma.h"

#include <algorithm>
#include <cstring>

namespace zb::vp {

namespace {
constexpr uint32_t kBusBytes = 8;  // a DMI access is timed as a burst of these beats
}

uint8_t* DmaPort::held(tlm::tlm_command cmd, uint64_t addr, size_t len) const {
  if (!use_dmi_ || !dmi_valid_ || addr < dmi_.get_start_address() ||
      addr + len - 1 > dmi_.get_end_address())
    return nullptr;
  if (!(cmd == tlm::TLM_READ_COMMAND ? dmi_.is_read_allowed() : dmi_.is_write_allowed()))
    return nullptr;
  return dmi_.get_dmi_ptr() + (addr - dmi_.get_start_address());
}

void DmaPort::ask_dmi(tlm::tlm_fw_transport_if<>& fw, tlm::tlm_command cmd, uint64_t addr) {
  tlm::tlm_generic_payload req;
  req.set_command(cmd);
  req.set_address(addr);
  tlm::tlm_dmi d;
  if (fw.get_direct_mem_ptr(req, d)) {
    dmi_ = d;
    dmi_valid_ = true;
    ++counts_.dmi_grants;
  }
}

void DmaPort::charge(tlm_utils::tlm_quantumkeeper& qk, tlm::tlm_command cmd, size_t len) {
  const uint64_t beats = (len + kBusBytes - 1) / kBusBytes;
  qk.inc((cmd == tlm::TLM_READ_COMMAND ? dmi_.get_read_latency() : dmi_.get_write_latency()) *
         double(beats));
  ++counts_.dmi_accesses;
  counts_.bytes += len;
}

uint8_t* DmaPort::view(tlm::tlm_fw_transport_if<>& fw, tlm_utils::tlm_quantumkeeper& qk,
                       tlm::tlm_command cmd, uint64_t addr, size_t len) {
  if (!use_dmi_ || len == 0) return nullptr;
  if (qk.need_sync()) qk.sync();
  if (uint8_t* p = held(cmd, addr, len)) return p;
  ask_dmi(fw, cmd, addr);
  return held(cmd, addr, len);
}

tlm::tlm_response_status DmaPort::access(tlm::tlm_fw_transport_if<>& fw,
                                         tlm_utils::tlm_quantumkeeper& qk, tlm::tlm_command cmd,
                                         uint64_t addr, uint8_t* data, size_t len,
                                         uint64_t& failed) {
  const bool read = cmd == tlm::TLM_READ_COMMAND;
  while (len > 0) {
    if (uint8_t* p = held(cmd, addr, len)) {
      charge(qk, cmd, len);
      if (read) std::memcpy(data, p, len);
      else std::memcpy(p, data, len);
      if (qk.need_sync()) qk.sync();
      return tlm::TLM_OK_RESPONSE;
    }
    const size_t n = std::min<size_t>(len, burst_);
    tlm::tlm_generic_payload tx;
    set_payload(tx, cmd, addr, data, n);
    sc_core::sc_time delay = qk.get_local_time();
    fw.b_transport(tx, delay);
    qk.set(delay);
    ++counts_.transactions;
    if (tx.is_response_error()) {
      failed = addr;
      return tx.get_response_status();
    }
    counts_.bytes += n;
    if (use_dmi_ && tx.is_dmi_allowed() && !held(cmd, addr, 1)) ask_dmi(fw, cmd, addr);
    if (qk.need_sync()) qk.sync();
    addr += n;
    data += n;
    len -= n;
  }
  return tlm::TLM_OK_RESPONSE;
}

void DmaPort::invalidate(uint64_t start, uint64_t end) {
  if (dmi_valid_ && start <= dmi_.get_end_address() && end >= dmi_.get_start_address()) {
    dmi_valid_ = false;
    ++counts_.dmi_invalidations;
  }
}

}  // namespace zb::vp
