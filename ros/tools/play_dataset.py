#!/usr/bin/python3
"""Plays one sequence of the public dataset to a running scbt_node and records what it publishes.

    play_dataset.py --dataset DIR --sequence Bowl [--node /scbt] [--rate 30] [--out results/]
                    [--max-frames N]

Frames (OriginalVideosAVI/<Seq>/NNNN.jpg) go out as bgr8 sensor_msgs/Image on --image (default
/camera/image_raw, what the launch file's node reads), stamped 1/rate apart; the ground truth's
first polygon initialises the node through <node>/init. Each frame's boundary is matched to it by stamp and
written to <out>/<Seq>.txt, one polygon per frame (a frame the node dropped gets the boundary
published before it: what a subscriber had then), so `scbt eval --results ros=<out>` scores it.
--rate 0 plays lock-step: each frame after the previous one's boundary came back (nothing
dropped). --max-frames N plays only the first N frames. Frames are read from disk one at a time
as they are sent, so a long sequence takes the memory of one frame. Prints frames sent,
boundaries received and the node's dropped/missed counts.
"""
import argparse
import json
import os
import sys
import threading
import time

import cv2


def frame_names(frames_dir, max_frames=0):
    """The sequence's frame files (NNNN.jpg) in order, at most max_frames of them (0: all)."""
    names = sorted(f for f in os.listdir(frames_dir) if f.endswith(".jpg"))
    return names[:max_frames] if max_frames > 0 else names


def read_frames(frames_dir, names):
    """Yields the frames one by one, each read when it is asked for (never the whole sequence)."""
    for name in names:
        path = os.path.join(frames_dir, name)
        frame = cv2.imread(path, cv2.IMREAD_COLOR)
        if frame is None:
            raise RuntimeError(f"{path}: cannot read the image")
        yield frame


def read_polygon(line):
    values = [float(v) for v in line.split()]
    n = int(values[0])
    return [(values[1 + 2 * i], values[2 + 2 * i]) for i in range(n)]


def to_image_msg(frame, stamp, seq):
    msg = Image()
    msg.header.stamp = stamp
    msg.header.seq = seq
    msg.header.frame_id = "camera"
    msg.height, msg.width = frame.shape[:2]
    msg.encoding = "bgr8"
    msg.step = frame.shape[1] * 3
    msg.data = frame.tobytes()
    return msg


def main():
    # ROS is needed to play, not to list or read the frames (play_dataset_test.py).
    import rospy
    from geometry_msgs.msg import Point32, PolygonStamped
    from sensor_msgs.msg import Image
    from std_msgs.msg import String

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dataset", required=True)
    parser.add_argument("--sequence", required=True)
    parser.add_argument("--node", default="/scbt", help="the node's name (its ~ namespace)")
    parser.add_argument("--image", default="/camera/image_raw", help="the topic the node reads")
    parser.add_argument("--rate", type=float, default=30.0, help="frames per second; 0: lock-step")
    parser.add_argument("--out", default="ros-results", help="folder for <Seq>.txt")
    parser.add_argument("--max-frames", type=int, default=0,
                        help="play only the first N frames (0: all)")
    args = parser.parse_args()
    if args.max_frames < 0:
        parser.error(f"--max-frames must be >= 0, got {args.max_frames}")

    frames_dir = os.path.join(args.dataset, "OriginalVideosAVI", args.sequence)
    truth_file = os.path.join(args.dataset, "GroundTruthByPolygons",
                              args.sequence + "_TrackingGroundTruth.txt")
    names = frame_names(frames_dir, args.max_frames)
    if not names:
        sys.exit(f"{frames_dir}: no NNNN.jpg frames")
    with open(truth_file) as f:
        init = read_polygon(f.readline(1 << 20))
    print(f"{args.sequence}: {len(names)} frames", file=sys.stderr)
    frames = read_frames(frames_dir, names)
    first_frame = next(frames)

    rospy.init_node("scbt_dataset_player", anonymous=True, disable_signals=True)
    image_pub = rospy.Publisher(args.image, Image, queue_size=len(names))
    init_pub = rospy.Publisher(args.node + "/init", PolygonStamped, queue_size=1, latch=True)
    lock = threading.Condition()
    boundaries = {}  # stamp (ns) -> polygon
    events = []
    last_state = {}
    timings = []  # (tracker total ms, latency ms) of every tracked frame
    tracker_states = []  # (state, confidence) of every tracked frame

    def on_boundary(msg):
        with lock:
            boundaries[msg.header.stamp.to_nsec()] = [(p.x, p.y) for p in msg.polygon.points]
            lock.notify_all()

    def on_state(msg):
        state = json.loads(msg.data)
        with lock:
            events.append(state["event"])
            last_state.update(state)
            if state["event"] == "tracked":
                timings.append((state["timings_ms"]["total"], state["timings_ms"]["latency"]))
                tracker_states.append((state["state"], state["confidence"]))
            lock.notify_all()

    rospy.Subscriber(args.node + "/boundary", PolygonStamped, on_boundary, queue_size=100000)
    rospy.Subscriber(args.node + "/state", String, on_state, queue_size=100000)
    deadline = time.time() + 20
    while image_pub.get_num_connections() == 0 or init_pub.get_num_connections() == 0:
        if time.time() > deadline:
            sys.exit(f"no node reads {args.image} and {args.node}/init")
        time.sleep(0.05)
    time.sleep(0.5)  # the node's subscriptions to us settle

    msg = PolygonStamped()
    msg.header.stamp = rospy.Time.now()
    msg.polygon.points = [Point32(x=x, y=y, z=0.0) for x, y in init]
    init_pub.publish(msg)
    # The init and the first frame travel on different connections: the first frame is sent
    # (same stamp) until the node reports it initialised on it.
    t0 = rospy.Time(1000)
    stamps = [t0 + rospy.Duration.from_sec(k / (args.rate or 30.0)) for k in range(len(names))]
    for attempt in range(50):
        with lock:
            events.clear()
        image_pub.publish(to_image_msg(first_frame, stamps[0], 0))
        with lock:
            lock.wait_for(lambda: events, timeout=5)
            if events and events[0] == "initialised":
                break
    else:
        sys.exit("the node never reported initialised")

    start = time.time()
    for k, frame in enumerate(frames, start=1):
        if args.rate > 0:
            time.sleep(max(0.0, start + k / args.rate - time.time()))
        image_pub.publish(to_image_msg(frame, stamps[k], k))
        if args.rate == 0:
            with lock:
                if not lock.wait_for(lambda: stamps[k].to_nsec() in boundaries, timeout=10):
                    sys.exit(f"no boundary for frame {k + 1}")
    elapsed = time.time() - start
    with lock:  # the last frame's boundary, or its being dropped, settles
        lock.wait_for(lambda: stamps[-1].to_nsec() in boundaries, timeout=5)
    time.sleep(0.5)

    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, args.sequence + ".txt")
    received = 0
    previous = init
    with lock, open(path, "w") as out:
        for stamp in stamps:
            polygon = boundaries.get(stamp.to_nsec())
            if polygon is not None:
                received += 1
                previous = polygon
            out.write(f"{len(previous)} " +
                      " ".join(f"{x:.2f} {y:.2f}" for x, y in previous) + "\n")
        state = dict(last_state)
        totals = sorted(t for t, _ in timings)
        latencies = sorted(l for _, l in timings)
        counts = {s: sum(1 for t, _ in tracker_states if t == s)
                  for s in ("tracking", "uncertain", "lost")}
        confidences = sorted(c for _, c in tracker_states)
    print(f"{args.sequence}: sent {len(names)} frames in {elapsed:.2f} s "
          f"({(len(names) - 1) / max(elapsed, 1e-9):.1f} fps), {received} boundaries received, node "
          f"dropped {state.get('dropped_frames')} and missed {state.get('missed_frames')}; "
          f"wrote {path}", file=sys.stderr)
    if totals:
        def pct(values, q):
            return values[min(len(values) - 1, int(q * len(values)))]
        print(f"{args.sequence}: tracker time per frame median {pct(totals, 0.5):.2f} ms, "
              f"95th percentile {pct(totals, 0.95):.2f} ms; image-to-boundary latency median "
              f"{pct(latencies, 0.5):.2f} ms, 95th percentile {pct(latencies, 0.95):.2f} ms",
              file=sys.stderr)
        print(f"{args.sequence}: ~state over the tracked frames: "
              + ", ".join(f"{s} {n}" for s, n in counts.items())
              + f"; confidence median {pct(confidences, 0.5):.3f}, 5th percentile "
              f"{pct(confidences, 0.05):.3f}", file=sys.stderr)
    rospy.signal_shutdown("done")


if __name__ == "__main__":
    main()
