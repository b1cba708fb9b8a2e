package io.orchard.viewer.model.vrml;

import static org.assertj.core.api.Assertions.assertThat;

import io.orchard.viewer.model.ModelException;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Token;
import io.orchard.viewer.model.vrml.VrmlTokenizer.Type;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class VrmlTokenizerTest {

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource({
        "0, true", "-1, true", "+2.5, true", ".5, true", "5., true", "1e10, true",
        "1.5E-3, true", "0x1F, true", "-0xff, true",
        "NaN, false", "Infinity, false", "1f, false", "1.2.3, false", "e5, false",
        "0x, false", "1e, false", "., false", "-, false", "1_000, false"})
    void numbersFollowTheVrmlGrammar(String word, boolean isNumber) {
        assertThat(VrmlTokenizer.isNumber(word)).isEqualTo(isNumber);
    }

    @Test
    void routeNamesSplitAtThePeriod() throws ModelException {
        assertThat(types("ROUTE Clock.fraction_changed TO Ramp.set_fraction")).containsExactly(
                Type.IDENT, Type.IDENT, Type.PERIOD, Type.IDENT, Type.IDENT, Type.IDENT,
                Type.PERIOD, Type.IDENT, Type.EOF);
    }

    @Test
    void tokensKnowTheirLineAndColumn() throws ModelException {
        VrmlTokenizer tokens = new VrmlTokenizer("Group {\n  # comment\n  children [ ]\n}");
        tokens.next();
        tokens.next();

        Token children = tokens.next();

        assertThat(children.text()).isEqualTo("children");
        assertThat(children.location()).isEqualTo("line 3:3");
    }

    @Test
    void wordsThatAreNeitherNumbersNorNamesAreInvalidTokens() throws ModelException {
        assertThat(types("1x 'quoted'")).containsExactly(Type.INVALID, Type.INVALID,
                Type.EOF);
    }

    private static List<Type> types(String text) throws ModelException {
        VrmlTokenizer tokens = new VrmlTokenizer(text);
        List<Type> types = new ArrayList<>();
        Token token;
        do {
            token = tokens.next();
            types.add(token.type());
        } while (!token.is(Type.EOF));
        return types;
    }
}
