/* libFuzzer target: the Dynamixel packet parser and unstuffer on arbitrary bytes.
 * First byte selects protocol / status mode / max_params; the parser is run over the whole
 * input as a stream (as the bus does), and every parsed packet is rebuilt and reparsed. */
#include "dynamixel/dynamixel.h"

#include <stdlib.h>
#include <string.h>

static dxl_packet pkt, again;
static uint8_t out[DXL_MAX_PACKET];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  int protocol = (data[0] & 1) ? 2 : 1;
  int is_status = (data[0] >> 1) & 1;
  size_t max_params = (size_t)(data[0] >> 2) * 17;   /* 0 (= default) .. 1071 */
  data++; size--;
  /* copy into an exact-size heap buffer so ASan sees any read past the end */
  uint8_t *buf = malloc(size ? size : 1);
  if (!buf) return 0;
  memcpy(buf, data, size);
  size_t pos = 0;
  while (pos < size) {
    size_t used = 0;
    int r = dxl_parse(protocol, is_status, buf + pos, size - pos, max_params, &pkt, &used);
    if (used > size - pos) abort();             /* never claims bytes it was not given */
    if (r == 1) {
      if (pkt.nparams > DXL_MAX_PARAMS) abort();
      /* a valid status packet rebuilds to one that parses to the same content */
      if (pkt.protocol == 2 && pkt.instruction == DXL_INST_STATUS) {
        int n = dxl_build_status(2, pkt.id, pkt.error, pkt.params, pkt.nparams, out, sizeof out);
        size_t u2;
        if (n > 0 && (dxl_parse(2, 1, out, (size_t)n, 0, &again, &u2) != 1 ||
                      again.nparams != pkt.nparams || again.error != pkt.error ||
                      memcmp(again.params, pkt.params, pkt.nparams) != 0))
          abort();
      }
    }
    if (r < 0 && used == 0) abort();            /* an error must make progress */
    if (used == 0) break;                       /* needs more bytes */
    pos += used;
  }
  uint8_t *u = malloc(size ? size : 1);
  if (u) {
    int n = dxl_unstuff(buf, size, u, size);
    if (n > (int)size) abort();
    free(u);
  }
  free(buf);
  return 0;
}
