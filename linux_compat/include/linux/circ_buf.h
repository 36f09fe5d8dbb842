/*
 * linux/circ_buf.h — the power-of-two ring buffer index macros, as Linux's
 * (include/linux/circ_buf.h): head is where the producer writes, tail where
 * the consumer reads, size a power of two; one slot always stays empty.
 */
#ifndef _LINUX_CIRC_BUF_H
#define _LINUX_CIRC_BUF_H

struct circ_buf {
	char *buf;
	int head;
	int tail;
};

/* Bytes in the buffer. */
#define CIRC_CNT(head, tail, size)	(((head) - (tail)) & ((size) - 1))

/* Free slots (one is always kept empty to tell full from empty). */
#define CIRC_SPACE(head, tail, size)	CIRC_CNT((tail), ((head) + 1), (size))

/* Bytes readable without wrapping: up to the end of the array or the head. */
#define CIRC_CNT_TO_END(head, tail, size) \
	({ int end_ = (size) - (tail); \
	   int n_ = ((head) + end_) & ((size) - 1); \
	   n_ < end_ ? n_ : end_; })

/* Free slots writable without wrapping. */
#define CIRC_SPACE_TO_END(head, tail, size) \
	({ int end_ = (size) - 1 - (head); \
	   int n_ = (end_ + (tail)) & ((size) - 1); \
	   n_ <= end_ ? n_ : end_ + 1; })

#endif /* _LINUX_CIRC_BUF_H */
