/*
 * startup.S — reset entry of the link-check firmware for the EV3 (AM1808).
 *
 * U-Boot loads the image at 0xC0008000 in DDR and jumps to its first word,
 * in SVC mode with the MMU and caches off.  We mask IRQ/FIQ, set up the SVC
 * stack, clear .bss and call fw_main; the real HRP2 kernel's start code does
 * the same before it initialises its objects.
 */
	.syntax unified
	.arm
	.section .text.reset, "ax"
	.global _start
	.type   _start, %function
_start:
	msr     cpsr_c, #0xD3           /* SVC mode, IRQ and FIQ masked */
	ldr     sp, =__stack_top
	ldr     r0, =__bss_start
	ldr     r1, =__bss_end
	mov     r2, #0
1:	cmp     r0, r1
	strlo   r2, [r0], #4
	blo     1b
	bl      fw_main
2:	b       2b
	.size   _start, . - _start
