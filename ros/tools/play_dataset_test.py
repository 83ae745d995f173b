#!/usr/bin/python3
"""play_dataset.py without ROS: the frame limit, and frames read one at a time as they are sent."""
import os
import sys
import tempfile
import unittest

import cv2
import numpy as np

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import play_dataset  # noqa: E402


class PlayDatasetTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.frames = self.dir.name
        for k in range(1, 6):
            image = np.full((24, 32, 3), 40 * k, np.uint8)
            cv2.imwrite(os.path.join(self.frames, f"{k:04d}.jpg"), image)

    def tearDown(self):
        self.dir.cleanup()

    def test_max_frames_limits_the_frames_played(self):
        self.assertEqual(play_dataset.frame_names(self.frames, 3),
                         ["0001.jpg", "0002.jpg", "0003.jpg"])
        self.assertEqual(len(play_dataset.frame_names(self.frames)), 5)
        self.assertEqual(len(play_dataset.frame_names(self.frames, 0)), 5)

    def test_frames_are_read_as_they_are_sent(self):
        frames = play_dataset.read_frames(self.frames, play_dataset.frame_names(self.frames))
        self.assertEqual(next(frames).shape, (24, 32, 3))
        # A frame not yet sent is not in memory: removed now, it is missed when its turn comes.
        os.remove(os.path.join(self.frames, "0003.jpg"))
        self.assertEqual(next(frames).shape, (24, 32, 3))
        with self.assertRaisesRegex(RuntimeError, "0003.jpg: cannot read the image"):
            next(frames)


if __name__ == "__main__":
    unittest.main()
