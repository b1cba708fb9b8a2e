package io.orchard.agents.language;

import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ObjectNode;

/**
 * An OpenAI-compatible chat completions endpoint on a port of its own, answering every request
 * with the content it is given, as a language model server would: for tests, with no model.
 */
public final class FakeLanguageModel implements AutoCloseable {

    private static final JsonMapper MAPPER = JsonMapper.builder().build();

    private final HttpServer server;
    private final List<JsonNode> requests = new CopyOnWriteArrayList<>();
    private volatile String content = "{\"goal\":null}";
    private volatile int status = 200;
    private volatile Duration delay = Duration.ZERO;

    /** Starts it on a free port of the loopback interface. */
    public FakeLanguageModel() throws IOException {
        server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        server.createContext("/v1/chat/completions", exchange -> {
            try (exchange) {
                requests.add(MAPPER.readTree(exchange.getRequestBody().readAllBytes()));
                Thread.sleep(delay.toMillis());
                ObjectNode answer = MAPPER.createObjectNode();
                answer.put("id", "chatcmpl-1").put("object", "chat.completion");
                answer.putArray("choices").addObject().put("index", 0).put("finish_reason", "stop")
                        .putObject("message").put("role", "assistant").put("content", content);
                byte[] body = MAPPER.writeValueAsBytes(answer);
                exchange.getResponseHeaders().add("Content-Type", "application/json");
                exchange.sendResponseHeaders(status, body.length);
                try (OutputStream out = exchange.getResponseBody()) {
                    out.write(body);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        server.start();
    }

    /** What the model answers from now on, as the text of its message. */
    public FakeLanguageModel answers(String content) {
        this.content = content;
        return this;
    }

    /** The HTTP status it answers with from now on. */
    public FakeLanguageModel status(int status) {
        this.status = status;
        return this;
    }

    /** How long it thinks before answering. */
    public FakeLanguageModel delay(Duration delay) {
        this.delay = delay;
        return this;
    }

    /** The bodies of the requests it received, in order. */
    public List<JsonNode> requests() {
        return List.copyOf(requests);
    }

    /** The model's settings for an interpreter, with this timeout. */
    public LanguageModel model(Duration timeout) {
        return new LanguageModel(URI.create("http://127.0.0.1:" + server.getAddress().getPort() + "/v1"), "fake-model",
                timeout);
    }

    @Override
    public void close() {
        server.stop(0);
    }
}
