/*
 * app_malloc.c — an EV3RT app's malloc family and C++ operators new and
 * delete on the apps' heap (app_heap.c).
 *
 * On the brick an app's malloc is newlib's over the heap EV3RT gives the
 * app's domain (APP_HEAP_SIZE, 1 MiB, in TDOM_APP: public source
 * ev3rt-git/ev3rt-hrp2, target/ev3_gcc/ev3.h and drivers/brick/src/brick_dri.c,
 * heap_for_domain), so memory an app allocated may be handed to any API
 * call: a colour read into a `new`ed rgb_raw_t works.  The host's app build
 * (mk/ev3rt_app.mk) renames the app's references to these calls
 * (mk/ev3rt_app_heap.syms) to the ev3rt_app_* functions below.
 *
 * Memory the host's C and C++ libraries allocated for the app inside their
 * own code (a std::string's buffer, strdup) is the host's; the app's free
 * and delete hand it back there, so either kind may be freed by the app.
 * Exhausting the heap is what it is on the brick: malloc returns NULL, and
 * a throwing operator new stops the app with a message.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "api_internal.h"

/* The renamed calls (nothing but an app's objects calls them).  C++'s
 * operators keep their mangled names after the prefix; size_t mangles as
 * m on LP64 hosts and as j where it is 32 bits (i386, ARM). */
void *ev3rt_app_malloc(size_t size);
void *ev3rt_app_calloc(size_t count, size_t size);
void *ev3rt_app_realloc(void *p, size_t size);
void ev3rt_app_free(void *p);
int ev3rt_app_posix_memalign(void **out, size_t alignment, size_t size);
void *ev3rt_app_aligned_alloc(size_t alignment, size_t size);
void *ev3rt_app_memalign(size_t alignment, size_t size);
void *ev3rt_app__Znwm(size_t size);
void *ev3rt_app__Znwj(size_t size);
void *ev3rt_app__Znam(size_t size);
void *ev3rt_app__Znaj(size_t size);
void *ev3rt_app__ZnwmRKSt9nothrow_t(size_t size, const void *nothrow);
void *ev3rt_app__ZnwjRKSt9nothrow_t(size_t size, const void *nothrow);
void *ev3rt_app__ZnamRKSt9nothrow_t(size_t size, const void *nothrow);
void *ev3rt_app__ZnajRKSt9nothrow_t(size_t size, const void *nothrow);
void ev3rt_app__ZdlPv(void *p);
void ev3rt_app__ZdaPv(void *p);
void ev3rt_app__ZdlPvm(void *p, size_t size);
void ev3rt_app__ZdlPvj(void *p, size_t size);
void ev3rt_app__ZdaPvm(void *p, size_t size);
void ev3rt_app__ZdaPvj(void *p, size_t size);
void ev3rt_app__ZdlPvRKSt9nothrow_t(void *p, const void *nothrow);
void ev3rt_app__ZdaPvRKSt9nothrow_t(void *p, const void *nothrow);

/* The heap's own alignment: anything stricter is refused. */
#define APP_HEAP_ALIGN  16U

/* Whether p lies in the apps' heap (else the host's libraries allocated it). */
static bool in_app_heap(const void *p)
{
	const uint8_t *at = p;

	return at >= api_app_heap && at < api_app_heap + sizeof(api_app_heap);
}

/* size bytes of the apps' heap; malloc(0) is a unique pointer, as newlib's. */
void *ev3rt_app_malloc(size_t size)
{
	void *p = api_app_heap_alloc(size == 0 ? 1U : (SIZE)size);

	if (p == NULL)
		errno = ENOMEM;
	return p;
}

/* count * size zeroed bytes, NULL (ENOMEM) when the product overflows. */
void *ev3rt_app_calloc(size_t count, size_t size)
{
	size_t total;
	void *p;

	if (__builtin_mul_overflow(count, size, &total)) {
		errno = ENOMEM;
		return NULL;
	}
	p = ev3rt_app_malloc(total);
	if (p != NULL)
		memset(p, 0, total);
	return p;
}

/* Frees p: the apps' heap's block, or the host's memory. */
void ev3rt_app_free(void *p)
{
	if (p == NULL)
		return;
	if (!in_app_heap(p)) {
		free(p);
		return;
	}
	if (api_app_heap_free(p) != E_OK) {
		syslog(LOG_ERROR, "free(%p): not a block of the app's heap, or freed already", p);
		abort();
	}
}

/* p resized to size, moved within the apps' heap when it must grow. */
void *ev3rt_app_realloc(void *p, size_t size)
{
	SIZE old;
	void *moved;

	if (p == NULL)
		return ev3rt_app_malloc(size);
	if (!in_app_heap(p))
		return realloc(p, size);
	if (size == 0) {
		ev3rt_app_free(p);
		return NULL;
	}
	old = api_app_heap_usable_size(p);
	if (old >= size)
		return p;
	moved = ev3rt_app_malloc(size);
	if (moved == NULL)
		return NULL;            /* p is left as it was, as C requires */
	memcpy(moved, p, old);
	ev3rt_app_free(p);
	return moved;
}

/* size bytes aligned to alignment (a power of two up to the heap's 16). */
int ev3rt_app_posix_memalign(void **out, size_t alignment, size_t size)
{
	void *p;

	if (alignment == 0 || (alignment & (alignment - 1U)) != 0 || alignment % sizeof(void *) != 0)
		return EINVAL;
	if (alignment > APP_HEAP_ALIGN) {
		syslog(LOG_ERROR, "posix_memalign: alignment %u is above the app heap's %u",
		       (unsigned)alignment, APP_HEAP_ALIGN);
		return ENOMEM;
	}
	p = ev3rt_app_malloc(size);
	if (p == NULL)
		return ENOMEM;
	*out = p;
	return 0;
}

/* As posix_memalign, returning the block (NULL and errno on failure). */
void *ev3rt_app_aligned_alloc(size_t alignment, size_t size)
{
	void *p = NULL;
	int err = ev3rt_app_posix_memalign(&p, alignment < sizeof(void *) ? sizeof(void *) : alignment, size);

	if (err != 0) {
		errno = err;
		return NULL;
	}
	return p;
}

/* memalign: aligned_alloc's contract (an obsolete name apps still use). */
void *ev3rt_app_memalign(size_t alignment, size_t size)
{
	return ev3rt_app_aligned_alloc(alignment, size);
}

/* operator new and new[]: the apps' heap, or the app stops when it is full
 * (an app built for EV3RT gets no std::bad_alloc it could count on). */
void *ev3rt_app__Znwm(size_t size)
{
	void *p = ev3rt_app_malloc(size);

	if (p == NULL) {
		syslog(LOG_ERROR, "operator new(%u): the app's heap (%u bytes) is full",
		       (unsigned)size, (unsigned)sizeof(api_app_heap));
		abort();
	}
	return p;
}
void *ev3rt_app__Znwj(size_t size) __attribute__((alias("ev3rt_app__Znwm")));
void *ev3rt_app__Znam(size_t size) __attribute__((alias("ev3rt_app__Znwm")));
void *ev3rt_app__Znaj(size_t size) __attribute__((alias("ev3rt_app__Znwm")));

/* operator new(size, std::nothrow) and new[]: NULL when the heap is full. */
void *ev3rt_app__ZnwmRKSt9nothrow_t(size_t size, const void *nothrow)
{
	(void)nothrow;
	return ev3rt_app_malloc(size);
}
void *ev3rt_app__ZnwjRKSt9nothrow_t(size_t size, const void *nothrow)
	__attribute__((alias("ev3rt_app__ZnwmRKSt9nothrow_t")));
void *ev3rt_app__ZnamRKSt9nothrow_t(size_t size, const void *nothrow)
	__attribute__((alias("ev3rt_app__ZnwmRKSt9nothrow_t")));
void *ev3rt_app__ZnajRKSt9nothrow_t(size_t size, const void *nothrow)
	__attribute__((alias("ev3rt_app__ZnwmRKSt9nothrow_t")));

/* operator delete and delete[], plain, sized and nothrow: free's contract. */
void ev3rt_app__ZdlPv(void *p)
{
	ev3rt_app_free(p);
}
void ev3rt_app__ZdaPv(void *p) __attribute__((alias("ev3rt_app__ZdlPv")));

void ev3rt_app__ZdlPvm(void *p, size_t size)
{
	(void)size;
	ev3rt_app_free(p);
}
void ev3rt_app__ZdlPvj(void *p, size_t size) __attribute__((alias("ev3rt_app__ZdlPvm")));
void ev3rt_app__ZdaPvm(void *p, size_t size) __attribute__((alias("ev3rt_app__ZdlPvm")));
void ev3rt_app__ZdaPvj(void *p, size_t size) __attribute__((alias("ev3rt_app__ZdlPvm")));

void ev3rt_app__ZdlPvRKSt9nothrow_t(void *p, const void *nothrow)
{
	(void)nothrow;
	ev3rt_app_free(p);
}
void ev3rt_app__ZdaPvRKSt9nothrow_t(void *p, const void *nothrow)
	__attribute__((alias("ev3rt_app__ZdlPvRKSt9nothrow_t")));
