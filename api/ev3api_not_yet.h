/*
 * ev3api_not_yet.h — the mark of a call of a group ev3lx does not provide
 * yet (included by the group headers of ev3api.h).
 *
 * The call is declared with EV3RT's signature, so an app using it compiles,
 * but bound to a symbol no library defines, so its link fails naming it:
 *   undefined reference to `ev3lx_not_yet_supported__lcd__ev3_lcd_draw_string'
 * A group that becomes available drops the mark from its declarations.
 */
#ifndef EV3API_NOT_YET_H
#define EV3API_NOT_YET_H

#ifdef __cplusplus
extern "C" {
#endif

#define EV3API_NOT_YET(group, name) __asm__("ev3lx_not_yet_supported__" #group "__" #name)

#ifdef __cplusplus
}
#endif

#endif /* EV3API_NOT_YET_H */
