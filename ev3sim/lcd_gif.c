/*
 * lcd_gif.c — ev3sim --lcd-video: the display over time as an animated GIF
 * through giflib (the program only, like lcd_png.c: the test configurations,
 * ARM ones included, link the library without it).  The panel is sampled at
 * every step of the run (10 ms of virtual time); a frame is kept when it
 * differs from the last one, and shown until the next (its delay, in the
 * GIF's hundredths of a second, is the virtual time between them).  Past
 * MAX_FRAMES changes the recording stops; the file holds the first ones.
 */
#define _POSIX_C_SOURCE 200809L       /* strdup */
#include <gif_lib.h>
#include <stdlib.h>
#include <string.h>
#include "ev3sim/run.h"
#include "host_sim/devices/ev3_lcd.h"

#define MAX_FRAMES 4096U         /* 4096 x 22 KiB: ~90 MiB at most */

struct frame {
	uint8_t px[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];
	uint64_t at_ns;
};

static struct {
	char *path;
	struct frame *frames;
	unsigned n;
	bool overflow;
} video;

/* Starts a recording to path. */
static ER video_begin(const char *path)
{
	free(video.frames);
	free(video.path);
	memset(&video, 0, sizeof(video));
	video.path = strdup(path);
	video.frames = calloc(MAX_FRAMES, sizeof(*video.frames));
	return video.path && video.frames ? E_OK : E_NOMEM;
}

/* Samples the panel at now_ns; keeps it if it changed. */
static void video_frame(uint64_t now_ns)
{
	struct frame *f;

	if (!video.frames)
		return;
	if (video.n == MAX_FRAMES) {
		video.overflow = true;
		return;
	}
	f = &video.frames[video.n];
	ev3_lcd_pixels(f->px);
	if (video.n > 0 && memcmp(f->px, video.frames[video.n - 1].px, sizeof(f->px)) == 0)
		return;
	f->at_ns = now_ns;
	video.n++;
}

/* Hundredths of a second from a to b, at least 1 (a GIF shows a 0 delay as "as fast as it can"). */
static int delay_cs(uint64_t a, uint64_t b)
{
	uint64_t cs = (b - a + 5000000U) / 10000000U;

	return cs < 1 ? 1 : cs > 65535 ? 65535 : (int)cs;
}

/* Writes the frames (the last shown until end_ns); E_OK or E_SYS. */
static ER video_end(uint64_t end_ns)
{
	static const GifColorType colors[2] = { { 255, 255, 255 }, { 0, 0, 0 } };   /* light, dark */
	static const unsigned char loop[3] = { 1, 0, 0 };                             /* loop forever */
	ColorMapObject *map = GifMakeMapObject(2, colors);
	GifFileType *gif;
	int err = 0;
	bool ok;

	gif = map ? EGifOpenFileName(video.path, false, &err) : NULL;
	ok = gif != NULL;
	if (ok) {
		EGifSetGifVersion(gif, true);
		ok = EGifPutScreenDesc(gif, EV3_LCD_PANEL_WIDTH, EV3_LCD_PANEL_HEIGHT, 1, 0, map) == GIF_OK &&
		     EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_OK &&
		     EGifPutExtensionBlock(gif, 11, "NETSCAPE2.0") == GIF_OK &&
		     EGifPutExtensionBlock(gif, 3, loop) == GIF_OK &&
		     EGifPutExtensionTrailer(gif) == GIF_OK;
	}
	for (unsigned i = 0; ok && i < video.n; i++) {
		GraphicsControlBlock gcb = {
			.DisposalMode = DISPOSAL_UNSPECIFIED, .UserInputFlag = false,
			.DelayTime = delay_cs(video.frames[i].at_ns, i + 1 < video.n ? video.frames[i + 1].at_ns : end_ns),
			.TransparentColor = NO_TRANSPARENT_COLOR,
		};
		GifByteType ext[4];

		EGifGCBToExtension(&gcb, ext);
		ok = EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, sizeof(ext), ext) == GIF_OK &&
		     EGifPutImageDesc(gif, 0, 0, EV3_LCD_PANEL_WIDTH, EV3_LCD_PANEL_HEIGHT, false, NULL) == GIF_OK;
		for (unsigned y = 0; ok && y < EV3_LCD_PANEL_HEIGHT; y++)
			ok = EGifPutLine(gif, video.frames[i].px[y], EV3_LCD_PANEL_WIDTH) == GIF_OK;
	}
	if (gif && EGifCloseFile(gif, &err) != GIF_OK)
		ok = false;
	GifFreeMapObject(map);
	free(video.frames);
	free(video.path);
	memset(&video, 0, sizeof(video));
	return ok ? E_OK : E_SYS;
}

static const struct ev3sim_lcd_video recorder = { video_begin, video_frame, video_end };

/* Installs the recorder before the command line runs (as lcd_png.c does). */
__attribute__((constructor)) static void lcd_gif_install(void)
{
	ev3sim_lcd_video = &recorder;
}
