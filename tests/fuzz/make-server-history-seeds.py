#!/usr/bin/env python3
"""Writes tests/fuzz/server_history-corpus: GetTelemetryResponse pages (each a 16-bit big-endian length
and the message) made from the telemetry of hci_telemetry-corpus/position-heading-battery-mode.bin
with times inside fuzz_server_history's range. Run from the repository's root."""
import struct
def rv(b,i):
    r=0;s=0
    while True:
        c=b[i];i+=1;r|=(c&0x7f)<<s;s+=7
        if c<0x80: return r,i
def fields(b):
    i=0;out=[]
    while i<len(b):
        k,i=rv(b,i);f,w=k>>3,k&7
        if w==0: v,i=rv(b,i)
        elif w==2:
            l,i=rv(b,i);v=b[i:i+l];i+=l
        elif w==1: v=b[i:i+8];i+=8
        elif w==5: v=b[i:i+4];i+=4
        out.append((f,w,v))
    return out
def ev(v):
    o=b''
    while True:
        c=v&0x7f;v>>=7
        if v: o+=bytes([c|0x80])
        else: return o+bytes([c])
def enc(f,w,v):
    k=ev(f<<3|w)
    if w==0: return k+ev(v)
    if w==2: return k+ev(len(v))+v
    return k+v
src=open('tests/fuzz/hci_telemetry-corpus/position-heading-battery-mode.bin','rb').read()
tel=[v for f,w,v in fields(src) if f==3 and w==2]
def at(t, time):
    return b''.join(enc(f,w,(time if f==2 else v)) for f,w,v in fields(t))
base=1764670000000
def page(times, nxt=None):
    body=b''.join(enc(3,2,at(tel[i%len(tel)],tm)) for i,tm in enumerate(times))
    if nxt is not None: body=enc(2,0,nxt)+body
    return struct.pack('>H',len(body))+body
# two pages: ten values a second for 3 s, the server saying where to go on, then the last page
p1=page([base+100*i for i in range(30)], base+3000)
p2=page([base+3000+100*i for i in range(30)])
open('tests/fuzz/server_history-corpus/two-pages.bin','wb').write(p1+p2)
# a page whose next time does not move forward: the history ends there
open('tests/fuzz/server_history-corpus/next-time-backwards.bin','wb').write(page([base+500*i for i in range(8)], base)+p2)
# values outside the range (before it, after it) among good ones
open('tests/fuzz/server_history-corpus/values-outside-the-range.bin','wb').write(page([base-5000, base+10, base+20, base+3600000+1, base+30]))
# unordered times in one page
open('tests/fuzz/server_history-corpus/unordered-times.bin','wb').write(page([base+2500, base+100, base+1900, base+1000, base+1001]))
