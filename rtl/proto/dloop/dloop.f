// rtl/proto/dloop: the two-steps-ahead step loop prototype (issue 15; docs/rtl-proto.md).
proto/dloop/dloop.v
proto/dloop/dloop1.v
proto/dloop/dloop1l.v
proto/dloop/dloop1x.v
