// the room included by run/bad.h
