/*
 * sil.h — TOPPERS System Interface Layer: interrupt lock, memory-mapped
 * register access, and short busy delays.
 *
 * AM1808 (EV3LX_AM1808): the real thing — CPSR I/F masking and volatile
 * accesses, as the HRP2 target's sil.h does.
 * Host (EV3LX_HOST): the same names, but register accesses go through the
 * handler host_sim installs (rtos_host.h: rtos_host_set_mmio_handler), so
 * every access has declared semantics, and delays advance virtual time.
 */
#ifndef TOPPERS_SIL_H
#define TOPPERS_SIL_H

#ifdef __cplusplus
extern "C" {
#endif

#include "t_stddef.h"

#if defined(EV3LX_AM1808)

#define SIL_ENDIAN_LITTLE

/* Saves the CPSR and masks IRQ and FIQ; SIL_UNL_INT restores the saved state. */
#define SIL_PRE_LOC   uint32_t sil_saved_cpsr_
#define SIL_LOC_INT() do { \
	uint32_t sil_tmp_; \
	__asm__ volatile("mrs %0, cpsr" : "=r"(sil_saved_cpsr_)); \
	sil_tmp_ = sil_saved_cpsr_ | 0xC0U; \
	__asm__ volatile("msr cpsr_c, %0" : : "r"(sil_tmp_) : "memory", "cc"); \
} while (0)
#define SIL_UNL_INT() \
	__asm__ volatile("msr cpsr_c, %0" : : "r"(sil_saved_cpsr_) : "memory", "cc")

static inline uint8_t  sil_reb_mem(const uint8_t *mem)  { return *(const volatile uint8_t *)mem; }
static inline void     sil_wrb_mem(uint8_t *mem, uint8_t data)   { *(volatile uint8_t *)mem = data; }
static inline uint16_t sil_reh_mem(const uint16_t *mem) { return *(const volatile uint16_t *)mem; }
static inline void     sil_wrh_mem(uint16_t *mem, uint16_t data) { *(volatile uint16_t *)mem = data; }
static inline uint32_t sil_rew_mem(const uint32_t *mem) { return *(const volatile uint32_t *)mem; }
static inline void     sil_wrw_mem(uint32_t *mem, uint32_t data) { *(volatile uint32_t *)mem = data; }

/* The kernel's calibrated busy loop (HRP2's ARM core: core_support.S's
 * _sil_dly_nse, which sil_dly_nse calls, arch/arm_gcc/common/core_sil.h). */
void _sil_dly_nse(ulong_t dlytim);

/* Busy-waits at least dlytim ns. */
static inline void sil_dly_nse(ulong_t dlytim) { _sil_dly_nse(dlytim); }

#else /* host */

#define SIL_ENDIAN_LITTLE

/* Host: the all-interrupt lock is the host kernel's interrupt mask, nesting-safe. */
uint_t sil_host_loc_int(void);              /* masks interrupts, returns the previous state */
void   sil_host_unl_int(uint_t saved);      /* restores the state sil_host_loc_int returned */

#define SIL_PRE_LOC   uint_t sil_saved_lock_
#define SIL_LOC_INT() (sil_saved_lock_ = sil_host_loc_int())
#define SIL_UNL_INT() sil_host_unl_int(sil_saved_lock_)

/* Register accesses of exact width, routed to the installed MMIO handler. */
uint32_t sil_host_read(const volatile void *mem, uint_t width);
void     sil_host_write(volatile void *mem, uint_t width, uint32_t data);

static inline uint8_t  sil_reb_mem(const uint8_t *mem)  { return (uint8_t)sil_host_read(mem, 1U); }
static inline void     sil_wrb_mem(uint8_t *mem, uint8_t data)   { sil_host_write(mem, 1U, data); }
static inline uint16_t sil_reh_mem(const uint16_t *mem) { return (uint16_t)sil_host_read(mem, 2U); }
static inline void     sil_wrh_mem(uint16_t *mem, uint16_t data) { sil_host_write(mem, 2U, data); }
static inline uint32_t sil_rew_mem(const uint32_t *mem) { return sil_host_read(mem, 4U); }
static inline void     sil_wrw_mem(uint32_t *mem, uint32_t data) { sil_host_write(mem, 4U, data); }

/* Host: the calling context spends dlytim ns of virtual CPU time (events fire meanwhile). */
void sil_dly_nse(ulong_t dlytim);

#endif

#ifdef __cplusplus
}
#endif

#endif /* TOPPERS_SIL_H */
