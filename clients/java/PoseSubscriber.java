// A robot-side subscriber in Java: receives the cell's part_pose_t messages on COSMOS_POSE
// and prints one line per part with every field, as the robot's pick logic would read them.
//
//   javac -cp /usr/share/java/lcm.jar:/usr/share/java/cosmos_lcm_types.jar PoseSubscriber.java
//   java -Djava.net.preferIPv4Stack=true \
//     -cp /usr/share/java/lcm.jar:/usr/share/java/cosmos_lcm_types.jar:. PoseSubscriber
//
// Options: --url URL (default: $LCM_DEFAULT_URL, else LCM's udpm default, which the cell
// publishes on), --count N (exit after N poses), --timeout-s S (exit 1 when S seconds pass first).
// The pose is T_cell_part: x_cell = R(orientation_wxyz) * x_part + position_m; it holds at
// encoder_ticks, so a robot tracking the conveyor moves it by the belt travel since then.

import cosmos_lcm.part_pose_t;
import java.io.IOException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import lcm.lcm.LCM;
import lcm.lcm.LCMDataInputStream;
import lcm.lcm.LCMSubscriber;

public class PoseSubscriber implements LCMSubscriber {
  public static final String POSE_CHANNEL = "COSMOS_POSE";

  private final CountDownLatch remaining;

  private PoseSubscriber(int count) {
    remaining = new CountDownLatch(count);
  }

  public static String statusName(byte status) {
    switch (status) {
      case part_pose_t.OK: return "OK";
      case part_pose_t.REJECTED: return "REJECTED";
      case part_pose_t.ERROR: return "ERROR";
      default: return "UNKNOWN(" + status + ")";
    }
  }

  private static String vector(double[] values) {
    StringBuilder text = new StringBuilder();
    for (int i = 0; i < values.length; ++i) text.append(i == 0 ? "" : ",").append(values[i]);
    return text.toString();
  }

  // One line per pose; the reason (free text) comes last.
  public static String line(part_pose_t pose) {
    return "pose seq=" + pose.part_seq + " part=" + (pose.part_name.isEmpty() ? "-" : pose.part_name)
        + " status=" + statusName(pose.status) + " part_index=" + pose.part_index
        + " view_index=" + pose.view_index + " utime=" + pose.utime
        + " encoder_ticks=" + pose.encoder_ticks + " position_m=" + vector(pose.position_m)
        + " orientation_wxyz=" + vector(pose.orientation_wxyz) + " score=" + pose.score
        + " registration_rms_mm=" + pose.registration_rms_mm + " latency_ms=" + pose.latency_ms
        + " reason=" + pose.reason;
  }

  @Override
  public synchronized void messageReceived(LCM lcm, String channel, LCMDataInputStream input) {
    try {
      System.out.println(line(new part_pose_t(input)));
      System.out.flush();
      remaining.countDown();
    } catch (IOException error) {
      System.err.println("PoseSubscriber: " + channel + ": not a part_pose_t: " + error.getMessage());
    }
  }

  public static void main(String[] args) throws Exception {
    String url = null;
    int count = Integer.MAX_VALUE;
    double timeoutSeconds = Double.POSITIVE_INFINITY;
    for (int i = 0; i < args.length; ++i) {
      String option = args[i];
      if (i + 1 >= args.length) usage(option + " needs a value");
      String value = args[++i];
      try {
        if (option.equals("--url")) url = value;
        else if (option.equals("--count")) count = Integer.parseInt(value);
        else if (option.equals("--timeout-s")) timeoutSeconds = Double.parseDouble(value);
        else usage("unknown option " + option);
      } catch (NumberFormatException error) {
        usage(option + " '" + value + "': not a number");
      }
    }
    LCM lcm = url == null ? new LCM() : new LCM(url);
    PoseSubscriber subscriber = new PoseSubscriber(count);
    lcm.subscribe(POSE_CHANNEL, subscriber);
    System.err.println("PoseSubscriber: listening on " + POSE_CHANNEL);
    boolean all = Double.isInfinite(timeoutSeconds)
        ? waitForever(subscriber.remaining)
        : subscriber.remaining.await((long) (timeoutSeconds * 1000), TimeUnit.MILLISECONDS);
    if (!all) {
      System.err.println("PoseSubscriber: fewer than " + count + " poses within " + timeoutSeconds + " s");
      System.exit(1);
    }
    System.exit(0);
  }

  private static boolean waitForever(CountDownLatch latch) throws InterruptedException {
    latch.await();
    return true;
  }

  private static void usage(String reason) {
    System.err.println("PoseSubscriber: " + reason
        + " (options: --url URL, --count N, --timeout-s S)");
    System.exit(2);
  }
}
